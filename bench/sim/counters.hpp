// The counters every step benchmark reports (rates per second of wall time, all
// threads together; docs/verification/performance.md defines them):
//   particles           particles the benchmarked operation covers;
//   particle_steps      particles advanced (or evaluated) per second;
//   pair_updates        operator entries (or particle pairs) processed per second;
//   bytes_per_particle  operator + state memory of the bodies involved, per particle.
// and the extra counters of some benchmarks, set to 0 here for the others.
#pragma once

#include <benchmark/benchmark.h>

namespace rkpm::sim {
struct Body;
struct World;
}  // namespace rkpm::sim

namespace rkpm::bench {

void set_counters(benchmark::State& state, double particles, double pair_entries, double bytes_per_particle);

// operator + state bytes of the Body (or World) divided by its particles.
double bytes_per_particle(const sim::Body& body);
double bytes_per_particle(const sim::World& world);

}  // namespace rkpm::bench
