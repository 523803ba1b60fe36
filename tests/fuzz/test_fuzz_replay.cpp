// Replays the fuzz seeds and the minimised corpus (tests/fuzz/seeds, tests/fuzz/corpus)
// through the fuzz targets. Each input must come back normally (accepted, or
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

// Each target's replay: the valid inputs among its seeds must be accepted (the example
// scenes load, the valid meshes import, the valid scripts mesh), the rest refused.
struct Replay {
  const char* target;
  Outcome (*run)(const std::uint8_t*, std::size_t);
};

class FuzzReplay : public ::testing::TestWithParam<Replay> {};

TEST_P(FuzzReplay, InputsComeBackAcceptedOrRefused) {
  const Replay& r = GetParam();
  const Counts counts = replay(r.target, r.run);
  std::cout << r.target << " inputs: " << counts.accepted << " accepted, " << counts.refused << " refused\n";
  EXPECT_GT(counts.accepted, 0) << "the valid inputs among the seeds must be accepted";
  EXPECT_GT(counts.refused, 0);
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzReplay,
                         ::testing::Values(Replay{"scene", scene_text}, Replay{"vtu", vtu_file},
                                           Replay{"msh", msh_file}, Replay{"geo", geo_file}),
                         [](const auto& test_info) { return std::string(test_info.param.target); });

TEST(FuzzReplay, CheckpointInputs) {
  // A checkpoint of this build is accepted (the committed seeds may predate a format
  // change and then are refusals like any other input).
  const std::string fresh = checkpoint_seed();
  EXPECT_EQ(checkpoint_file(reinterpret_cast<const std::uint8_t*>(fresh.data()), fresh.size()), Outcome::Accepted);
  const Counts counts = replay("checkpoint", checkpoint_file);
  std::cout << "checkpoint inputs: " << counts.accepted << " accepted, " << counts.refused << " refused\n";
  EXPECT_GT(counts.refused, 0);
}

}  // namespace
}  // namespace rkpm::fuzz
