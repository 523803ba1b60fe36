// Pre-flight: what a scene will cost, from the scene file alone, before anything large
// is allocated. `rkpm check` (and `rkpm run --dry-run`) prints it; `rkpm run` refuses a
// scene whose estimate exceeds the memory it may use, the index range of the arrays or
// the free space of its output folder, naming the key that sets the size.
//
// The counts are exact for the generators (block: (nx+1)(ny+1)(nz+1) particles; sphere:
// (n+1)^3; shell: layers (6 n^2 + 2)) and read from the file's NumberOfPoints for an
// imported .vtu. The operator entries are a model of the row lengths: the particles
// whose support (radius `support` times the longest edge) covers a point, counted in the
// ball of that radius clipped to the body's extent (docs/verification/performance.md compares it with
// built operators). Memory is the operators at their set-up peak (rows built as lists,
// then flattened) plus the per-particle state; a frame is counted uncompressed, an upper
// bound of what the zlib-compressed .vtu takes.
#pragma once

#include "rkpm/scene/scene.hpp"

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rkpm::sim {

struct BodyEstimate {
  std::string name;
  std::string generator;
  std::string size_key;           // the key (with its line) that sets the particle count
  double particles = 0.0;         // double: a hostile scene may exceed every integer type
  double elements = 0.0;
  double gradient_entries = 0.0;  // smoothed-gradient operator entries (SCNI rows)
  double interpolation_entries = 0.0;
  double memory_bytes = 0.0;      // peak during set-up and run, on one rank
  std::string support_shape;      // what [body.rk] support_shape resolves to: "sphere" or "ellipsoid"
  // The same with [body.rk] support_shape = "ellipsoid" (memory_bytes when declared):
  // a refusal names the key when the ellipsoids would fit.
  double memory_bytes_with_ellipsoids = 0.0;
};

struct RunEstimate {
  std::vector<BodyEstimate> bodies;
  double particles = 0.0;
  // A distributed run: each rank builds the operator rows of its share of the particles
  // and (in this version) keeps the whole-length state arrays; the ranks on one node
  // share its memory.
  int ranks = 1;
  int ranks_on_node = 1;
  double memory_bytes = 0.0;          // one rank's peak
  double node_memory_bytes() const { return memory_bytes * ranks_on_node; }
  double frame_bytes = 0.0;           // one frame, uncompressed
  std::optional<double> frames;       // at most this many frames (one per `every` up to t_end, at
                                      // most one per step); empty when the scene does not bound them
  double checkpoint_bytes = 0.0;
  double output_bytes = 0.0;          // the bound on frames (or the first and last) + checkpoint
  // A relaxation with nested levels: the particles of each level it runs first, coarsest
  // first (nested_level_factors: the declared ones and any put before them).
  std::vector<double> level_particles;
};

// Limits a run must fit in. Absent: taken from the machine (available memory, cgroup
// limit and address-space limit; free space of the output folder's file system).
struct RunLimits {
  std::optional<double> memory_bytes;
  std::optional<double> disk_bytes;
};

// Raised by `check_limits`: the message names the scene file, the key, the estimate
// and the limit.
struct PreflightError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

RunEstimate estimate_run(const scene::Scene& scene, int ranks = 1, int ranks_on_node = 1);

// The memory this process may still use [bytes]: the least of MemAvailable, the cgroup's
// memory.max minus its usage, and the address-space limit (RLIMIT_AS) less what the
// process maps already. Empty when none is known.
std::optional<double> available_memory();
// Its parts: what the node (and the job's cgroup) has for all the processes on it, and
// what the address-space limit leaves this process alone.
std::optional<double> available_node_memory();
std::optional<double> available_address_space();
// Free space of the file system that holds `dir` (or its nearest existing parent).
std::optional<double> available_disk(const std::filesystem::path& dir);

// Throws PreflightError when the estimate does not fit: more particles or entries than
// the 32-bit particle index can address, more memory than `limits.memory_bytes` (or the
// machine's) for the ranks on this node. Called before anything is built.
void check_memory(const RunEstimate& estimate, const RunLimits& limits);

// Frames a run writes: with the step `dt` of a dynamic run known (after set-up), one per
// `every` or per step, whichever is fewer, up to t_end; without it the first and last
// only, which every run writes (relaxation's pseudo-time step grows and shrinks).
// `step_limit` > 0 (rkpm run --max-steps) bounds the steps, and so the frames, further.
double frames_expected(const scene::Scene& scene, const RunEstimate& estimate, std::optional<double> dt,
                       std::int64_t step_limit = 0);

// Throws PreflightError when `frames` frames and the checkpoint exceed the free space of
// `out_dir` (or limits.disk_bytes), naming [output] every.
void check_disk(const scene::Scene& scene, const RunEstimate& estimate, double frames, const RunLimits& limits,
                const std::filesystem::path& out_dir);

// The estimate as a short table, with the limits it is checked against.
void print_estimate(std::ostream& out, const scene::Scene& scene, const RunEstimate& estimate,
                    const RunLimits& limits, const std::filesystem::path& out_dir);

// "1.5 GB", "730 MB": sizes in messages.
std::string human_bytes(double bytes);

// Parses "8G", "512M", "2e9" for --memory-limit: bytes, with an optional unit K, M, G or
// T (powers of 1000). Throws std::invalid_argument naming the text.
double parse_byte_size(const std::string& text);

}  // namespace rkpm::sim
