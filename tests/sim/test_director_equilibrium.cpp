// The director's own equilibrium (seed Eq. 5-7).
// - Its distance from it (sim::director_residual): at F = I the part of dF/dh across h
//   is -mu (s-1)^2/s (h . h0) (h0 - (h . h0) h) (Eq. 6 at F = I, no Frank term), so a
//   director turned by theta from h0 gives (s-1)^2/s sin(theta) cos(theta) times mu; on
//   h0 it is zero.
// - The step that keeps its explicit update stable (sim::director_stable_dt): at F = I
//   the relaxation's matrix is mu (s-1)/s (I + (s-1) h0 h0^T), eigenvalues mu (s-1)/s
//   (twice) and mu (s-1), whose spread mu (s-1)^2/s is the stiffness on the unit sphere,
//   so the step is 2 s / (L mu (s-1)^2); a mobility at which it binds relaxes to rest
//   instead of swinging.
// - The stop that waits for it (relax_state_tol): a slow director is still turning
//   when the forces settle, and with the tolerance the relaxation goes on until it rests.
#include "sim_fixtures.hpp"

#include "rkpm/sim/body_state.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace rkpm::sim {
namespace {

const char* kBlockAtRest = R"([scene]
name = "director_residual"
[integrator]
mode = "relax"
[[body]]
name = "block"
density = 1000
[body.cloud]
generator = "block"
size = [1e-6, 1e-6, 1e-6]
cells = [{cells}, {cells}, {cells}]
[body.material]
model = "lce"
mu = 1e4
bulk = 1e5
s = 2.0
kappa = {kappa}
mobility = {mobility}
[body.director]
initial = "fixed"
vector = [0, 0, 1]
boundary = "free"
)";

std::string block(const std::string& mobility, const std::string& kappa, int cells) {
  std::string text = testing::with(kBlockAtRest, "mobility", mobility);
  text = testing::with(text, "kappa", kappa);
  return testing::with(text, "cells", std::to_string(cells));
}

double residual_with_director_turned_by(double theta) {
  testing::ScopedThreads one(1);
  auto sw = testing::build_from_text(block("1e3", "0", 3));
  Body& body = *sw.world->bodies.front();
  for (Vec3& h : materials::lce::material_of(body)->director.h) h = Vec3(std::sin(theta), 0.0, std::cos(theta));
  return state_residual(body);
}

TEST(DirectorResidual, ATurnedDirectorAtRestGivesTheClosedFormMolecularField) {
  const double s = 2.0;
  for (const double theta : {0.1, 0.3, 0.7}) {
    const double expected = (s - 1.0) * (s - 1.0) / s * std::sin(theta) * std::cos(theta);
    EXPECT_NEAR(residual_with_director_turned_by(theta), expected, 1e-9 * expected) << "theta = " << theta;
  }
  EXPECT_LT(residual_with_director_turned_by(0.0), 1e-14);
}

TEST(DirectorStableStep, AtRestItIsTwoOverMobilityTimesTheSpreadOfTheRelaxationMatrix) {
  testing::ScopedThreads one(1);
  auto sw = testing::build_from_text(block("1e5", "0", 3));
  const Body& body = *sw.world->bodies.front();
  const double mu = 1e4, s = 2.0, mobility = 1e5;
  const double expected = 2.0 * s / (mobility * mu * (s - 1.0) * (s - 1.0));
  EXPECT_NEAR(state_stable_dt(body), expected, 1e-12 * expected);
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  EXPECT_LT(integrator.stable_dt(), material_stable_dt(body)) << "the director's step binds";
  EXPECT_DOUBLE_EQ(integrator.stable_dt(), state_stable_dt(body));
}

// A director turned by +-0.5 rad in alternate particles, with a Frank term and a mobility
// at which the wave-speed step would put dt L times the director's stiffness bound at 16:
// the relaxation ends at rest with the director at its equilibrium too (1,697 steps
// measured). Without the director's limit the same run still had a residual of 0.27 mu
// after 20,000 steps: the explicit update swings.
TEST(DirectorStableStep, AHighMobilityRelaxesToRestInsteadOfSwinging) {
  testing::ScopedThreads one(1);
  auto sw = testing::build_from_text(block("1e5", "1e-10", 4));
  Body& body = *sw.world->bodies.front();
  for (std::size_t i = 0; i < materials::lce::material_of(body)->director.h.size(); ++i) {
    const double theta = i % 2 == 0 ? 0.5 : -0.5;
    materials::lce::material_of(body)->director.h[i] = Vec3(std::sin(theta), 0.0, std::cos(theta));
  }
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  EXPECT_GT(sw.settings.dt_safety * material_stable_dt(body) * 2.0 / state_stable_dt(body), 10.0);
  while (!integrator.converged() && sw.world->step < 20000) integrator.step();
  std::printf("%lld steps, residual %.3g mu, director residual %.3g\n", static_cast<long long>(sw.world->step),
              integrator.residual(), integrator.state_residual());
  EXPECT_TRUE(integrator.converged()) << "after " << sw.world->step << " steps";
  EXPECT_LT(integrator.state_residual(), 1e-3);
}

// A slow director: the forces and the motion settle long before it does. Without
// relax_state_tol the relaxation stops there, the director still turning; with it,
// it goes on until the director is at rest too.
struct SlowDirectorStop {
  std::int64_t steps = 0;
  bool converged = false;
  double director_residual = 0.0;
};

SlowDirectorStop relax_slow_director(double director_tol) {
  testing::ScopedThreads one(1);
  std::string text = block("3e1", "0", 3);
  text.replace(text.find("mode = \"relax\""), 14, "mode = \"relax\"\nrelax_state_tol = " + std::to_string(director_tol));
  auto sw = testing::build_from_text(text);
  EXPECT_EQ(sw.settings.relax_state_tol, director_tol) << "read from the scene's [integrator] table";
  Body& body = *sw.world->bodies.front();
  for (std::size_t i = 0; i < materials::lce::material_of(body)->director.h.size(); ++i) {
    const double theta = i % 2 == 0 ? 0.5 : -0.5;
    materials::lce::material_of(body)->director.h[i] = Vec3(std::sin(theta), 0.0, std::cos(theta));
  }
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  SlowDirectorStop stop;
  while (!(stop.converged = integrator.converged()) && sw.world->step < 100000) integrator.step();
  stop.steps = sw.world->step;
  stop.director_residual = integrator.state_residual();
  std::printf("relax_state_tol %g: %lld steps, converged %d, residual %.3g mu, director residual %.3g\n",
              director_tol, static_cast<long long>(stop.steps), stop.converged ? 1 : 0, integrator.residual(),
              stop.director_residual);
  return stop;
}

TEST(DirectorStop, WithAToleranceTheRelaxationWaitsForTheDirector) {
  const SlowDirectorStop forces_only = relax_slow_director(0.0);
  const SlowDirectorStop with_director = relax_slow_director(1e-4);
  ASSERT_TRUE(forces_only.converged && with_director.converged);
  // Measured: 4,888 steps to 4.6e-3 without the tolerance, 18,449 to 1.0e-4 with it.
  EXPECT_GT(forces_only.director_residual, 1e-3) << "the test needs a director still turning at the forces' stop";
  EXPECT_LT(with_director.director_residual, 1e-4);
  EXPECT_GT(with_director.steps, forces_only.steps);
}

// The Frank divergence is assembled in the force pass only for a reader in the step
// (DirectorField::frank_divergence_tracked): a relaxing director (L > 0) or a director
// criterion. A held director (L = 0) leaves it to director_residual, which then gives the
// residual of the tracked pass at the same state.
TEST(DirectorStop, TheFrankDivergenceIsTrackedOnlyWhereTheStepReadsIt) {
  testing::ScopedThreads one(1);
  const auto tracked_after_initialize = [](const std::string& text) {
    auto sw = testing::build_from_text(text);
    Body& body = *sw.world->bodies.front();
    Integrator integrator(*sw.world, sw.settings);
    integrator.initialize();
    return materials::lce::material_of(body)->director.frank_divergence_tracked;
  };
  const std::string held = block("0", "1e-11", 3), relaxing = block("1e3", "1e-11", 3);
  EXPECT_FALSE(tracked_after_initialize(held));
  EXPECT_TRUE(tracked_after_initialize(relaxing));
  std::string with_criterion = held;
  with_criterion.insert(with_criterion.find("[integrator]\n") + 13, "relax_state_tol = 1e-4\n");
  EXPECT_TRUE(tracked_after_initialize(with_criterion));

  // The held director's residual, untracked, against the same state with the pass tracking.
  auto sw = testing::build_from_text(held);
  Body& body = *sw.world->bodies.front();
  for (std::size_t i = 0; i < materials::lce::material_of(body)->director.h.size(); ++i) {
    const double theta = 0.3 * std::sin(static_cast<double>(i));
    materials::lce::material_of(body)->director.h[i] = Vec3(std::sin(theta), 0.0, std::cos(theta));
  }
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  ASSERT_FALSE(materials::lce::material_of(body)->director.frank_divergence_tracked);
  const double untracked = integrator.state_residual();
  materials::lce::material_of(body)->director.frank_divergence_tracked = true;
  compute_internal_forces(body);
  const double tracked = state_residual(body);
  ASSERT_GT(tracked, 0.0);
  EXPECT_NEAR(untracked, tracked, 1e-12 * tracked);
}

}  // namespace
}  // namespace rkpm::sim
