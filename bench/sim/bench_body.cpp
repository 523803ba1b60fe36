// Per-body step kernels: the internal force per material and the director update,
// and, for reference, one whole Integrator step of each scene.
#include "counters.hpp"
#include "fixtures.hpp"

#include "../common/footprint.hpp"
#include "rkpm/sim/body.hpp"
#include "rkpm/sim/body_state.hpp"
#include "rkpm/sim/world.hpp"

namespace rkpm::bench {

namespace {

// F, stress, internal force and stabilization of one body (sim::compute_internal_forces).
void internal_force(benchmark::State& state, SceneFixture& f, const char* body_name) {
  sim::Body& body = f.body(body_name);
  for (auto _ : state) {
    sim::compute_internal_forces(body);
    benchmark::DoNotOptimize(body.force.data());
    benchmark::ClobberMemory();
  }
  // Body::force now lacks the terms' forces: restore the total the integrator expects.
  sim::compute_forces(*f.world);
  set_counters(state, static_cast<double>(body.size()), internal_force_pair_updates(body), bytes_per_particle(body));
  // The compulsory traffic of one step (footprint.hpp), to compare with the triad.
  state.counters["bytes_moved"] = static_cast<double>(internal_force_traffic(body).total());
  // In 1e9 B/s, the unit of the scaling study's triad bound.
  state.counters["bandwidth"] = benchmark::Counter(static_cast<double>(internal_force_traffic(body).total()),
                                                   benchmark::Counter::kIsIterationInvariantRate);
}

void BM_InternalForce_MooneyRivlinBlock(benchmark::State& state) { internal_force(state, block_fixture(), "block"); }
void BM_InternalForce_LCEShell(benchmark::State& state) { internal_force(state, rbc_fixture(), "cell"); }
BENCHMARK(BM_InternalForce_MooneyRivlinBlock)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_InternalForce_LCEShell)->Unit(benchmark::kMillisecond)->UseRealTime();

// Eq. 5-8 on the RBC shell: the active work and the co-rotational rate from the step's
// motion F - F_start (no gather over the rows), Allen-Cahn with the Frank divergence,
// renormalisation, surface anchoring. The director keeps relaxing
// from iteration to iteration; the cost does not depend on how far it got.
void BM_DirectorUpdate_LCEShell(benchmark::State& state) {
  SceneFixture& f = rbc_fixture();
  sim::Body& body = f.body("cell");
  const double dt = f.integrator->dt();
  for (auto _ : state) {
    benchmark::DoNotOptimize(sim::end_state_step(body, dt));
    benchmark::ClobberMemory();
  }
  // Per particle only: no pairs.
  set_counters(state, static_cast<double>(body.size()), 0.0, bytes_per_particle(body));
}
BENCHMARK(BM_DirectorUpdate_LCEShell)->Unit(benchmark::kMillisecond)->UseRealTime();

// One Integrator step with everything the scene declares (terms, constraints,
// director, FIRE or damping, blow-up checks, periodic stable-step estimates).
void whole_step(benchmark::State& state, SceneFixture& f) {
  double entries = 0.0;
  for (const auto& b : f.world->bodies) entries += internal_force_pair_updates(*b);
  for (auto _ : state) f.integrator->step();
  set_counters(state, static_cast<double>(f.world->particle_count()), entries, bytes_per_particle(*f.world));
}

void BM_Step_MooneyRivlinBlock(benchmark::State& state) { whole_step(state, block_fixture()); }
void BM_Step_RBC(benchmark::State& state) { whole_step(state, rbc_fixture()); }
void BM_Step_Adhesion(benchmark::State& state) { whole_step(state, adhesion_fixture()); }
BENCHMARK(BM_Step_MooneyRivlinBlock)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Step_RBC)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Step_Adhesion)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

}  // namespace rkpm::bench
