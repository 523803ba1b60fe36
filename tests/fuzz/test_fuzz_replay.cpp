// Replays the fuzz seeds and the minimised corpus (tests/fuzz/seeds, tests/fuzz/corpus)
// through the two fuzz targets. Each input must come back normally (accepted, or
// refused with the layer's own error): under the sanitized build this is the
// regression test for everything the fuzzers found.
#include "fuzz_targets.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace rkpm::fuzz {
namespace {

namespace fs = std::filesystem;

const fs::path kFuzzDir = fs::path(RKPM_SOURCE_DIR) / "tests" / "fuzz";

std::vector<fs::path> files_in(const fs::path& dir) {
  std::vector<fs::path> files;
  if (!fs::is_directory(dir)) return files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<std::uint8_t> bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Counts {
  int accepted = 0;
  int refused = 0;
};

// Every file of seeds/<target> and corpus/<target> through `run`.
template <typename Target>
Counts replay(const std::string& target, Target run) {
  Counts counts;
  for (const char* set : {"seeds", "corpus"}) {
    for (const fs::path& file : files_in(kFuzzDir / set / target)) {
      SCOPED_TRACE(file.string());
      const std::vector<std::uint8_t> data = bytes_of(file);
      try {
        (run(data.data(), data.size()) == Outcome::Accepted ? counts.accepted : counts.refused)++;
      } catch (const std::exception& e) {
        ADD_FAILURE() << "unexpected exception: " << e.what();
      }
    }
  }
  return counts;
}

TEST(FuzzReplay, SceneInputs) {
  const Counts counts = replay("scene", scene_text);
  std::cout << "scene inputs: " << counts.accepted << " accepted, " << counts.refused << " refused\n";
  EXPECT_GT(counts.accepted, 0) << "the example scenes among the seeds must load";
  EXPECT_GT(counts.refused, 0);
}

TEST(FuzzReplay, VtuInputs) {
  const Counts counts = replay("vtu", vtu_file);
  std::cout << "vtu inputs: " << counts.accepted << " accepted, " << counts.refused << " refused\n";
  EXPECT_GT(counts.accepted, 0) << "the valid meshes among the seeds must import";
  EXPECT_GT(counts.refused, 0);
}

}  // namespace
}  // namespace rkpm::fuzz
