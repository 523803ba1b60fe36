// The parameter reference (docs/reference/parameters.md) is generated from the
// parameter tables; this test fails when a table changes and the page was not
// regenerated (scripts/update-params.sh).
#include "rkpm/scene/param_registry.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

TEST(ParameterReference, PageMatchesTheTables) {
  const std::string path = std::string(RKPM_SOURCE_DIR) + "/docs/reference/parameters.md";
  std::ifstream in(path);
  ASSERT_TRUE(in) << path << " not found";
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  const std::string begin = "<!-- BEGIN PARAMETER REFERENCE -->\n", end = "<!-- END PARAMETER REFERENCE -->";
  const auto b = text.find(begin), e = text.find(end);
  ASSERT_NE(b, std::string::npos) << path << " lacks its BEGIN marker";
  ASSERT_NE(e, std::string::npos) << path << " lacks its END marker";
  const std::string on_page = text.substr(b + begin.size(), e - b - begin.size());

  std::ostringstream generated;
  rkpm::scene::print_params(generated, rkpm::scene::ParamFormat::markdown);
  std::string expected = generated.str();
  while (!expected.empty() && expected.back() == '\n') expected.pop_back();
  EXPECT_EQ(on_page, expected + "\n") << path << " is out of date: run scripts/update-params.sh";
}
