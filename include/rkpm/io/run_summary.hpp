// summary.json: what a run did, in one small machine-readable file, so studies
// and CI can collect results without parsing logs.
#pragma once

#include "rkpm/io/json.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace rkpm::io {

struct RunSummary {
  std::string scene;                                               // scene file as given
  std::vector<std::pair<std::string, std::int64_t>> particle_counts;  // per body name, in scene order
  std::int64_t steps = 0;
  double simulated_time = 0.0;  // [s]
  double wall_time = 0.0;       // [s]
  std::int64_t frames_written = 0;
  std::string status = "completed";                          // e.g. "completed", "blow-up", "interrupted"
  std::vector<std::pair<std::string, double>> final_metrics;  // name -> value, in the order given
};

// The JSON layout of a summary:
// { "scene", "particle_counts": {body: n, ...}, "total_particles", "steps",
//   "simulated_time", "wall_time", "frames_written", "status", "final_metrics": {name: x, ...} }
Json to_json(const RunSummary& summary);

// Writes to_json(summary) atomically. Throws std::invalid_argument naming the
// key if a metric is NaN or infinite (nothing is written then).
void write_summary(const std::filesystem::path& path, const RunSummary& summary);

}  // namespace rkpm::io
