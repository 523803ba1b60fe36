#include "rkpm/io/run_summary.hpp"

namespace rkpm::io {

Json to_json(const RunSummary& summary) {
  Json counts = Json::object();
  std::int64_t total = 0;
  for (const auto& [body, n] : summary.particle_counts) {
    counts.set(body, n);
    total += n;
  }
  Json metrics = Json::object();
  for (const auto& [name, value] : summary.final_metrics) metrics.set(name, value);

  Json json = Json::object();
  json.set("scene", summary.scene)
      .set("particle_counts", std::move(counts))
      .set("total_particles", total)
      .set("steps", summary.steps)
      .set("simulated_time", summary.simulated_time)
      .set("wall_time", summary.wall_time)
      .set("frames_written", summary.frames_written)
      .set("status", summary.status)
      .set("final_metrics", std::move(metrics));
  return json;
}

void write_summary(const std::filesystem::path& path, const RunSummary& summary) {
  write_json_atomically(path, to_json(summary));
}

}  // namespace rkpm::io
