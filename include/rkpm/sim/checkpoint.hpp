// Checkpoints: the complete dynamic state of a run in one binary file, so that a
// run resumed from it with the same scene, build and thread count continues bit
// for bit as if it had never stopped. Operators built from the reference
// configuration are not stored: they are rebuilt deterministically from the scene.
#pragma once

#include "rkpm/sim/integrator.hpp"
#include "rkpm/sim/world.hpp"

#include <cstdint>
#include <filesystem>
#include <string>

namespace rkpm::sim {

struct RunClock {
  double next_output = 0.0;  // simulated time of the next frame
  std::int64_t frames = 0;   // frames written so far
};

// Writes atomically (temporary file, then rename). `scene_digest` identifies the
// scene text; a checkpoint is only loaded into the scene it came from.
void write_checkpoint(const std::filesystem::path& path, const World& world, const Integrator& integrator,
                      const RunClock& clock, std::uint64_t scene_digest);

// Loads into a world freshly built from the same scene. Throws std::runtime_error
// naming the file and what does not match (scene, particle counts, format).
void read_checkpoint(const std::filesystem::path& path, World& world, Integrator& integrator, RunClock& clock,
                     std::uint64_t scene_digest);

// FNV-1a digest of a file's bytes.
std::uint64_t file_digest(const std::filesystem::path& path);

}  // namespace rkpm::sim
