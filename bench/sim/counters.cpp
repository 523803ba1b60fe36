#include "counters.hpp"

#include "../common/footprint.hpp"

namespace rkpm::bench {

void set_counters(benchmark::State& state, double particles, double pair_entries, double bytes_per_particle) {
  using benchmark::Counter;
  // Google Benchmark's CSV has one header for all benchmarks and aborts on a counter
  // the first one did not have: every benchmark carries every counter, 0 if not its own.
  for (const char* name : {"bytes_moved", "bandwidth", "listed_pairs", "active_pairs", "faces", "file_bytes",
                           "write_rate"})
    state.counters[name] = 0.0;
  state.counters["particles"] = particles;
  state.counters["particle_steps"] = Counter(particles, Counter::kIsIterationInvariantRate);
  state.counters["pair_updates"] = Counter(pair_entries, Counter::kIsIterationInvariantRate);
  state.counters["bytes_per_particle"] = bytes_per_particle;
}

double bytes_per_particle(const sim::Body& body) {
  const Footprint f = footprint(body);
  return static_cast<double>(f.operators + f.state) / static_cast<double>(body.size());
}

double bytes_per_particle(const sim::World& world) {
  const Footprint f = footprint(world);
  return static_cast<double>(f.operators + f.state) / static_cast<double>(world.particle_count());
}

}  // namespace rkpm::bench
