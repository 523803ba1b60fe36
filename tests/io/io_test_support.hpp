// Shared fixtures for the output tests: a scratch directory and sample frames
// whose values use all 52 mantissa bits, so only a bit-exact round trip passes.
#pragma once

#include "rkpm/common/split_mix64.hpp"
#include "rkpm/io/frame.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace rkpm::io::test {

// Fresh directory per test, removed afterwards.
class ScratchDir : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = std::filesystem::temp_directory_path() /
          (std::string("rkpm_io_") + info->test_suite_name() + "_" + info->name() + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
  }
  void TearDown() override { std::filesystem::remove_all(dir); }

  std::filesystem::path dir;
};

using rkpm::SplitMix64;  // a fixed, portable sequence (std distributions are implementation-defined)

// A 2 x 2 x 1 block of hexahedra (3 x 3 x 2 = 18 points), jittered.
inline std::vector<Vec3> hex_block_points(std::uint64_t seed) {
  SplitMix64 rng(seed);
  std::vector<Vec3> points;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        points.emplace_back(i + rng.uniform(-0.1, 0.1), j + rng.uniform(-0.1, 0.1), k + rng.uniform(-0.1, 0.1));
  return points;
}

inline CellBlock hex_block_cells() {
  CellBlock cells;
  auto id = [](int i, int j, int k) { return static_cast<std::int64_t>(i + 3 * j + 9 * k); };
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 2; ++i) {
      // VTK_HEXAHEDRON ordering: bottom face counter-clockwise, then top face.
      for (std::int64_t p : {id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0), id(i, j, 1),
                             id(i + 1, j, 1), id(i + 1, j + 1, 1), id(i, j + 1, 1)}) {
        cells.connectivity.push_back(p);
      }
      cells.types.push_back(static_cast<std::uint8_t>(CellType::hexahedron));
      cells.offsets.push_back(static_cast<std::int64_t>(cells.connectivity.size()));
    }
  }
  return cells;
}

inline PointField random_field(const std::string& name, int components, std::size_t n_points, SplitMix64& rng,
                               double scale) {
  PointField f{name, components, {}};
  for (std::size_t k = 0; k < n_points * static_cast<std::size_t>(components); ++k) {
    f.values.push_back(rng.uniform(-scale, scale));
  }
  return f;
}

// The point fields the simulator writes: kinematics, ids, and what active terms provide.
inline std::vector<PointField> sample_fields(std::size_t n_points, std::uint64_t seed) {
  SplitMix64 rng(seed);
  std::vector<PointField> fields;
  fields.push_back(random_field("displacement", 3, n_points, rng, 1e-3));
  fields.push_back(random_field("velocity", 3, n_points, rng, 1e-1));
  PointField body{"body_id", 1, {}};
  for (std::size_t i = 0; i < n_points; ++i) body.values.push_back(static_cast<double>(i % 2));
  fields.push_back(body);
  fields.push_back(random_field("volume", 1, n_points, rng, 1.0));
  fields.push_back(random_field("cauchy_stress", 9, n_points, rng, 1e3));
  fields.push_back(random_field("von_mises", 1, n_points, rng, 1e3));
  fields.push_back(random_field("J", 1, n_points, rng, 1.0));
  fields.push_back(random_field("director", 3, n_points, rng, 1.0));
  return fields;
}

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::set<std::string> file_names(const std::filesystem::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) names.insert(entry.path().filename().string());
  return names;
}

}  // namespace rkpm::io::test
