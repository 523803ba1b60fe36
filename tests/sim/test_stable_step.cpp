// The measured stable step (stable_step.hpp): the power iteration's omega_max against
// the largest eigenvalue of the assembled, mass-weighted tangent of a small block, and
// 2 / omega_max against the closed-form stability limit of central differences: at
// omega dt = 2.1 the top mode grows by a factor 1.88 per step (r + 1/r = 2 - (omega dt)^2),
// at 1.9 every mode stays bounded.
#include "sim_fixtures.hpp"

#include "rkpm/sim/stable_step.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace rkpm::sim {
namespace {

using testing::build_from_text;
using testing::with;

// A jittered Mooney-Rivlin block; {stretch} pre-stretches it (the tangent is then not
// the reference one), {support} adds essential boundary conditions.
const std::string kBlock = R"([scene]
name = "stable_step"
[integrator]
t_end = 1.0
dt = {dt}
[[body]]
name = "block"
density = 1000
[body.cloud]
generator = "block"
size = [1, 0.8, 0.6]
cells = [3, 3, 2]
jitter = 0.15
[body.material]
model = "mooney_rivlin"
c1 = 400
c2 = 100
lambda = 2000
[body.initial]
stretch = {stretch}
{support})";

constexpr const char* kStretched = "[1.04, 0.98, 1.0]";
constexpr const char* kAtRest = "[1.0, 1.0, 1.0]";

std::string block(const std::string& dt, const std::string& stretch, const std::string& support) {
  return with(with(with(kBlock, "dt", dt), "stretch", stretch), "support", support);
}

const std::string kClamped = R"([[body.boundary]]
surface = "xmin"
axes = "xyz")";

// omega_max^2 of the free degrees of freedom, from the tangent assembled column by
// column by central differences of the integrator's (transformed) forces and the dense
// symmetric eigenvalue solver.
double dense_omega_max(World& world) {
  Body& b = *world.bodies[0];
  const std::vector<Vec3> d0 = b.d;
  std::vector<int> free;  // flat indices 3 I + axis of the free components
  for (std::size_t i = 0; i < b.size(); ++i)
    for (int axis = 0; axis < 3; ++axis)
      if (!b.constraints.constrained(static_cast<Index>(i), axis)) free.push_back(static_cast<int>(3 * i + axis));
  const auto n = static_cast<Eigen::Index>(free.size());
  Eigen::MatrixXd A(n, n);
  std::vector<Vec3> velocity(b.size());
  auto forces_at = [&](int dof, double h) {
    b.d = d0;
    b.d[dof / 3][dof % 3] += h;
    b.constraints.impose(b.d, velocity);
    compute_forces(world);
    b.constraints.transform_forces(b.force);
    return b.force;
  };
  const double h = 1e-7;
  for (Eigen::Index j = 0; j < n; ++j) {
    const int dof_j = free[static_cast<std::size_t>(j)];
    const std::vector<Vec3> plus = forces_at(dof_j, h), minus = forces_at(dof_j, -h);
    for (Eigen::Index i = 0; i < n; ++i) {
      const int dof_i = free[static_cast<std::size_t>(i)];
      const double k = -(plus[dof_i / 3][dof_i % 3] - minus[dof_i / 3][dof_i % 3]) / (2.0 * h);
      A(i, j) = k / std::sqrt(b.inertia[dof_i / 3] * b.inertia[dof_j / 3]);
    }
  }
  b.d = d0;
  compute_forces(world);
  b.constraints.transform_forces(b.force);
  const Eigen::MatrixXd symmetric = 0.5 * (A + A.transpose());
  std::printf("tangent asymmetry |A - A^T| / |A| = %.2e\n", (A - A.transpose()).norm() / A.norm());
  return std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(symmetric).eigenvalues().maxCoeff());
}

void expect_power_iteration_matches_dense(const std::string& support) {
  testing::ScopedThreads one(1);
  auto sw = build_from_text(block("0.0", kStretched, support));
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  const double dense = dense_omega_max(*sw.world);
  const FrequencyEstimate measured = largest_frequency(*sw.world, 200, 1e-6);
  std::printf("omega_max: power iteration %.6g rad/s in %d force evaluations, dense eigenvalue %.6g rad/s\n",
              measured.omega_max, measured.iterations, dense);
  EXPECT_NEAR(measured.omega_max, dense, 1e-3 * dense);
}

TEST(StableStep, PowerIterationFindsTheLargestEigenvalueOfTheTangent) { expect_power_iteration_matches_dense(""); }

TEST(StableStep, PowerIterationKeepsTheEssentialBoundaryConditions) { expect_power_iteration_matches_dense(kClamped); }

TEST(StableStep, TheStateIsLeftAsItWas) {
  testing::ScopedThreads one(1);
  auto sw = build_from_text(block("0.0", kStretched, kClamped));
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  const Body& b = *sw.world->bodies[0];
  const std::vector<Vec3> d = b.d, force = b.force;
  const std::vector<Mat3> F = b.F;
  largest_frequency(*sw.world);
  EXPECT_EQ(b.d, d);
  EXPECT_EQ(b.force, force);
  EXPECT_EQ(b.F, F);
}

std::string fmt_real(double x) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

// Kinetic plus strain energy after `steps` steps at dt = factor * 2 / omega_max from small
// velocities at rest, over the initial energy. The block is clamped so that it has no
// rigid motion; BlowUp counts as growth without bound.
double energy_growth(double factor, int steps) {
  testing::ScopedThreads one(1);
  auto probe = build_from_text(block("0.0", kAtRest, kClamped));
  Integrator probe_integrator(*probe.world, probe.settings);
  probe_integrator.initialize();
  const double critical = 2.0 / largest_frequency(*probe.world, 200, 1e-6).omega_max;

  auto sw = build_from_text(block(fmt_real(factor * critical), kAtRest, kClamped));
  sw.settings.allow_unstable_dt = true;
  sw.settings.measured_stable_step = false;
  Integrator integrator(*sw.world, sw.settings);
  Body& b = *sw.world->bodies[0];
  for (std::size_t i = 0; i < b.size(); ++i)
    b.v[i] = 1e-6 * Vec3(std::sin(1.0 + 3.0 * i), std::cos(2.0 + 5.0 * i), std::sin(7.0 * i));
  integrator.initialize();
  const double start = integrator.measure_energy().kinetic + integrator.measure_energy().strain;
  try {
    for (int s = 0; s < steps; ++s) integrator.step();
  } catch (const BlowUp&) {
    return INFINITY;
  }
  const auto& e = integrator.measure_energy();
  return (e.kinetic + e.strain) / start;
}

TEST(StableStep, TwoOverOmegaMaxIsTheStabilityLimitOfCentralDifferences) {
  const double below = energy_growth(0.95, 400), above = energy_growth(1.05, 400);
  std::printf("energy after 400 steps over the start: %.3g at 0.95 x 2/omega_max, %.3g at 1.05 x\n", below, above);
  EXPECT_LT(below, 2.0);
  EXPECT_GT(above, 1e6);
}

// The integrator's measured step: dt_safety x 2 / omega_max at the start.
TEST(StableStep, TheIntegratorTakesTheMeasuredStep) {
  testing::ScopedThreads one(1);
  auto sw = build_from_text(block("0.0", kStretched, kClamped));
  sw.settings.measured_stable_step = true;
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  const double critical = 2.0 / largest_frequency(*sw.world).omega_max;
  std::printf("measured stable step %.6g s, calibration %.4g of the wave-speed step\n", integrator.stable_dt(),
              integrator.stable_step_calibration());
  EXPECT_DOUBLE_EQ(integrator.stable_dt(), critical);
  EXPECT_DOUBLE_EQ(integrator.dt(), sw.settings.dt_safety * critical);
  EXPECT_EQ(integrator.calibrations(), 1);
}

// The motion limit of dynamic runs: released from a stretch of 2 (J = 2, where the
// volumetric energy is still convex), no particle moves more than kMotionFraction of
// its spacing in any step; the limit binds (the stable step alone would move some
// particle farther) and lets go in some steps (the step returns to the policy's step).
TEST(StableStep, NoParticleMovesMoreThanTheMotionFractionOfItsSpacingInAStep) {
  testing::ScopedThreads one(1);
  auto sw = build_from_text(block("0.0", "[2.0, 1.0, 1.0]", ""));
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  Body& b = *sw.world->bodies[0];
  double largest = 0.0;
  for (int s = 0; s < 300; ++s) {
    const std::vector<Vec3> before = b.d;
    integrator.step();
    for (std::size_t i = 0; i < b.size(); ++i) largest = std::max(largest, (b.d[i] - before[i]).norm() / b.spacing[i]);
  }
  std::printf("largest move per step %.4f of the spacing; %lld of 300 steps limited by the motion\n", largest,
              static_cast<long long>(integrator.motion_limited_steps()));
  EXPECT_LE(largest, Integrator::kMotionFraction * (1.0 + 1e-12));
  EXPECT_GT(integrator.motion_limited_steps(), 0);
  EXPECT_LT(integrator.motion_limited_steps(), 300);
}

}  // namespace
}  // namespace rkpm::sim
