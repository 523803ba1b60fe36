// Checkpoints: the complete dynamic state of a run in one binary file, so that a
// run resumed from it with the same scene, build and thread count continues bit
// for bit as if it had never stopped. Operators built from the reference
// configuration are not stored: they are rebuilt deterministically from the scene.
//
// The file holds named fields (a StateRecord: name, element type, components, count,
// the exact bytes) after a header with a format version, and ends with a digest of
// its content. The reader looks every field up by name, so a missing or mis-sized
// field, another format version, a truncated or corrupt file, or a checkpoint of
// another scene, body list, particle count or term list is an error naming the file
// and what differs.
#pragma once

#include "rkpm/sim/integrator.hpp"
#include "rkpm/sim/state_record.hpp"
#include "rkpm/sim/world.hpp"

#include <cstdint>
#include <filesystem>
#include <string>

namespace rkpm::sim {

struct RunClock {
  double next_output = 0.0;  // simulated time of the next frame
  std::int64_t frames = 0;   // frames written so far
};

// The named fields of a checkpoint: "scene_digest", "time", "step", "clock.*",
// "integrator.*" (Integrator::save_state), "bodies" (their names, one a line),
// "body.<name>.{particles,d,v,a,constraint_targets}" and its material's state fields, "terms" (their names)
// and "term.<k>.*" (Term::save_state of the k-th term).
StateRecord checkpoint_record(const World& world, const Integrator& integrator, const RunClock& clock,
                              std::uint64_t scene_digest);

// Writes atomically (temporary file, then rename). `scene_digest` identifies the
// scene text; a checkpoint is only loaded into the scene it came from.
void write_checkpoint(const std::filesystem::path& path, const World& world, const Integrator& integrator,
                      const RunClock& clock, std::uint64_t scene_digest);

// Loads into a world freshly built from the same scene. Throws std::runtime_error
// naming the file and what does not match (format version, scene, bodies, particle
// counts, terms, a missing or mis-sized field) or that the file is truncated or
// corrupt; the scene, body, particle and term checks come before anything is loaded.
void read_checkpoint(const std::filesystem::path& path, World& world, Integrator& integrator, RunClock& clock,
                     std::uint64_t scene_digest);

// FNV-1a digest of a file's bytes.
std::uint64_t file_digest(const std::filesystem::path& path);

}  // namespace rkpm::sim
