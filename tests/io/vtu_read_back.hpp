// Reads a .vtu through VTK's own reader, the way ParaView does, into plain
// vectors the tests can compare with what was written.
#pragma once

#include "rkpm/io/frame.hpp"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace rkpm::io::test {

struct ReadBack {
  bool points_are_float64 = false;
  std::vector<Vec3> points;
  CellBlock cells;
  std::map<std::string, PointField> point_fields;
  std::map<std::string, PointField> field_data;
  std::vector<std::uint8_t> ghost_type;  // vtkGhostType per point; empty if the frame has none
};

// Throws std::runtime_error if VTK reports an error reading `path`. A .pvtu (a
// distributed run's frame) is read with its pieces, as one grid.
ReadBack read_vtu_back(const std::filesystem::path& path);

}  // namespace rkpm::io::test
