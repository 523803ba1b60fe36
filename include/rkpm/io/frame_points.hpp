// Reads the particles of a frame written by a run (a .vtu, or a distributed run's
// .pvtu with its pieces), for commands that measure or compare finished runs
// (rkpm shape, rkpm compare).
//
// A distributed run's pieces list each rank's particles and a halo of copies, in the
// rank's numbering; the frame's body_id and particle_id fields (the particle's number
// in a one-rank run) put them back in the one-rank order, each particle once, so a
// frame reads the same whatever rank count wrote it. A frame without those fields
// (written before they existed) is read in file order.
#pragma once

#include "rkpm/common/types.hpp"

#include <filesystem>
#include <vector>

namespace rkpm::io {

struct FramePoints {
  std::vector<Vec3> position;      // every particle of every body, bodies in scene order
  std::vector<Vec3> displacement;  // the same order; empty if the frame has no displacement field
  std::vector<std::size_t> body_size;  // particles per body (one entry when the frame has no body_id)
};

// Throws std::runtime_error naming `path` when the file is missing, VTK cannot read it,
// it has no points, a coordinate is not finite, or its particle ids leave a gap.
FramePoints read_frame_points(const std::filesystem::path& path);

// `given` itself, or for a run's output directory the last frame its frames.pvd lists.
std::filesystem::path frame_file(const std::filesystem::path& given);

}  // namespace rkpm::io
