// bench_rk: throughput of the per-step mechanics on the default red-blood-cell shell
// (particles::make_shell(ShellSpec{}): 30,730 particles; cubic B-spline kernel,
// support 2, linear basis, SCNI), and the set-up cost of its gradient operator.
//
// Counters (rates are per second of wall time, all threads together):
//   particle_steps  particles advanced per second (one internal-force evaluation
//                   per particle = one particle-step);
//   pair_updates    entries of the gradient operator b_I(X_L) processed per second:
//                   the step reads every entry twice, once in the gather for F and
//                   once in the transposed gather for the force;
//   interp_updates  the same for the nodal-interpolation operator Psi_I(X_L) in the
//                   stabilization force (also read twice).
#include "materials/mooney_rivlin/mooney_rivlin.hpp"
#include "rkpm/particles/generators.hpp"
#include "rkpm/rk/nodal_integration.hpp"
#include "rkpm/rk/rk_approximation.hpp"
#include "rkpm/rk/stabilization.hpp"

#include <benchmark/benchmark.h>

#include <vector>

namespace {

using namespace rkpm;

// The shell and its operators, built once for all benchmarks.
struct ShellSetup {
  particles::Cloud cloud = particles::make_shell(particles::ShellSpec{});
  rk::RKApproximation rk{cloud, rk::RKSettings{}};
  rk::GradientOperator gradient = rk::build_gradient_operator(cloud, rk, rk::Integration::SCNI);
  rk::NodalInterpolation interpolation = rk::build_nodal_interpolation(cloud, rk);
  // Cell-like Mooney-Rivlin parameters: mu = 2 (c1 + c2) = 1e4 Pa, bulk 4 lambda = 4e5 Pa.
  materials::MooneyRivlin material{2.0e3, 3.0e3, 1.0e5};

  // A smooth, finite deformation (stretch and shear) so the stress is not trivial.
  std::vector<Vec3> displacement() const {
    Mat3 A;
    A << 0.05, 0.02, 0.0, 0.0, -0.03, 0.01, 0.01, 0.0, 0.02;
    std::vector<Vec3> d(cloud.size());
    for (std::size_t i = 0; i < d.size(); ++i) d[i] = A * cloud.X[i];
    return d;
  }
};

const ShellSetup& shell() {
  static const ShellSetup setup;
  return setup;
}

// Google Benchmark's CSV output has one header for all benchmarks and aborts on a
// counter the first benchmark lacked: every benchmark sets every counter.
void declare_counters(benchmark::State& state) {
  for (const char* name : {"particles", "particle_steps", "pair_updates", "interp_updates", "entries_per_row"})
    state.counters[name] = 0.0;
}

void set_rates(benchmark::State& state, double particles, double pair_entries, const char* pair_name) {
  declare_counters(state);
  state.counters["particles"] = particles;
  state.counters["particle_steps"] = benchmark::Counter(particles, benchmark::Counter::kIsIterationInvariantRate);
  state.counters[pair_name] = benchmark::Counter(pair_entries, benchmark::Counter::kIsIterationInvariantRate);
}

// F_L = sum_I x_I (x) b_I(X_L), P_L = P(F_L), f_I = sum_L V_L P_L b_I(X_L).
void BM_InternalForce(benchmark::State& state) {
  const ShellSetup& s = shell();
  const std::vector<Vec3> d = s.displacement();
  std::vector<Vec3> x(d.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = s.cloud.X[i] + d[i];
  std::vector<Mat3> F, P(s.cloud.size());
  std::vector<Vec3> f;
  const auto n = static_cast<Index>(s.cloud.size());
  for (auto _ : state) {
    rk::deformation_gradients(s.gradient, x, F);
#pragma omp parallel for schedule(static)
    for (Index L = 0; L < n; ++L) P[L] = s.material.first_piola(F[L]);
    rk::internal_forces(s.gradient, P, f);
    benchmark::DoNotOptimize(f.data());
    benchmark::ClobberMemory();
  }
  set_rates(state, static_cast<double>(n), 2.0 * static_cast<double>(s.gradient.col.size()), "pair_updates");
}
BENCHMARK(BM_InternalForce)->Unit(benchmark::kMillisecond)->UseRealTime();

// The interpolation-residual stabilization force -(I - N)^T W (I - N) d.
void BM_StabilizationForce(benchmark::State& state) {
  const ShellSetup& s = shell();
  const std::vector<Vec3> d = s.displacement();
  rk::Stabilization stab =
      rk::build_stabilization(s.cloud.volume, std::vector<double>(s.cloud.size(), s.material.shear_modulus()), 0.1);
  std::vector<Vec3> f(d.size(), Vec3::Zero());
  for (auto _ : state) {
    benchmark::DoNotOptimize(rk::add_stabilization_forces(s.interpolation, stab, d, f));
    benchmark::ClobberMemory();
  }
  set_rates(state, static_cast<double>(s.cloud.size()), 2.0 * static_cast<double>(s.interpolation.col.size()),
            "interp_updates");
}
BENCHMARK(BM_StabilizationForce)->Unit(benchmark::kMillisecond)->UseRealTime();

// Set-up: the SCNI smoothed-gradient operator (RK shape functions at every
// quadrature point of every smoothing cell, then the transpose).
void BM_BuildGradientOperator(benchmark::State& state) {
  const ShellSetup& s = shell();
  std::size_t entries = 0;
  for (auto _ : state) {
    const rk::GradientOperator op = rk::build_gradient_operator(s.cloud, s.rk, rk::Integration::SCNI);
    entries = op.col.size();
    benchmark::DoNotOptimize(op.grad.data());
  }
  declare_counters(state);
  state.counters["particles"] = static_cast<double>(s.cloud.size());
  state.counters["entries_per_row"] = static_cast<double>(entries) / static_cast<double>(s.cloud.size());
}
BENCHMARK(BM_BuildGradientOperator)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
