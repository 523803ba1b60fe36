// The README's parameter reference is generated from the parameter tables; this
// test fails when a table changes and the README was not regenerated
// (scripts/update-readme.sh).
#include "rkpm/scene/param_registry.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

TEST(Readme, ParameterReferenceMatchesTheTables) {
  std::ifstream in(std::string(RKPM_SOURCE_DIR) + "/README.md");
  ASSERT_TRUE(in) << "README.md not found";
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  const std::string begin = "<!-- BEGIN PARAMETER REFERENCE -->\n", end = "<!-- END PARAMETER REFERENCE -->";
  const auto b = text.find(begin), e = text.find(end);
  ASSERT_NE(b, std::string::npos);
  ASSERT_NE(e, std::string::npos);
  const std::string in_readme = text.substr(b + begin.size(), e - b - begin.size());

  std::ostringstream generated;
  rkpm::scene::print_params(generated, rkpm::scene::ParamFormat::markdown);
  std::string expected = generated.str();
  while (!expected.empty() && expected.back() == '\n') expected.pop_back();
  EXPECT_EQ(in_readme, expected + "\n") << "README.md is out of date: run scripts/update-readme.sh";
}
