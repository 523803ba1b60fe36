// Reads the point positions of a frame written by the VTU writer (or any .vtu), for
// commands that measure a finished run (rkpm shape).
#pragma once

#include "rkpm/common/types.hpp"

#include <filesystem>
#include <vector>

namespace rkpm::io {

// Throws std::runtime_error naming `path` when the file is missing, VTK cannot read it,
// it has no points or a coordinate is not finite.
std::vector<Vec3> read_vtu_points(const std::filesystem::path& path);

}  // namespace rkpm::io
