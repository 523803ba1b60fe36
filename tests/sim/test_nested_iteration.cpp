// The relaxation accelerators of docs/verification/relaxation.md: nested iteration (the scene at a
// coarser resolution, the state carried to the finer cloud by the RK approximation),
// mass scaling and FIRE 2.0. Each must reach the same equilibrium as plain FIRE: the
// masses, the starting point and the velocity control of a static problem change the
// path, not the answer.
#include "rkpm/scene/resolution.hpp"
#include "rkpm/sim/nested_iteration.hpp"
#include "sim_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace rkpm::sim {
namespace {

// A jittered neo-Hookean block on rollers under tension on every face: a static
// problem without rigid motions, so two relaxations can be compared particle by particle.
const std::string kBlockOnRollers = R"([scene]
name = "nested"
[integrator]
mode = "relax"
relax_force_tol = 1e-7
relax_velocity_tol = 1e-12
max_steps = 200000
nested_levels = {levels}
mass_scaling = {mass_scaling}
relax_method = "{method}"
[[body]]
name = "block"
density = 1000
[body.cloud]
generator = "block"
size = [1, 0.6, 0.6]
cells = [10, 6, 6]
jitter = 0.1
[body.material]
model = "neo_hookean"
mu = 1000
lambda = 4000
[[body.boundary]]
surface = "xmin"
axes = "x"
[[body.boundary]]
surface = "ymin"
axes = "y"
[[body.boundary]]
surface = "zmin"
axes = "z"
[[term]]
type = "surface_pressure"
body = "block"
surface = "all"
pressure = -300
)";

std::string block_scene(const std::string& levels, bool mass_scaling, const std::string& method = "fire") {
  return testing::with(testing::with(testing::with(kBlockOnRollers, "levels", levels), "mass_scaling",
                                     mass_scaling ? "true" : "false"),
                       "method", method);
}

struct Relaxation {
  std::vector<Vec3> u;       // physical displacement at the particles
  std::int64_t steps = 0;    // on the scene's own cloud
  std::int64_t coarse_steps = 0;
  bool converged = false;
};

Relaxation relax(const std::string& toml) {
  auto sw = testing::build_from_text(toml);
  std::ostringstream log;
  Relaxation r;
  for (const LevelRun& level : relax_coarse_levels(sw.scene, *sw.world, log)) r.coarse_steps += level.steps;
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  while (sw.world->step < 200000 && !(r.converged = integrator.converged())) integrator.step();
  r.steps = sw.world->step;
  physical_displacement(*sw.world->bodies.front(), r.u);
  return r;
}

// max_I |a_I - b_I| / max_I |b_I|.
double relative_difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double diff = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    diff = std::max(diff, (a[i] - b[i]).norm());
    scale = std::max(scale, b[i].norm());
  }
  return diff / scale;
}

TEST(NestedIteration, TheSceneAtAnotherResolutionScalesEveryGeneratorsCellCounts) {
  const auto sw = testing::build_from_text(block_scene("[0.5]", false));
  const scene::Scene half = scene::at_resolution(sw.scene, 0.5);
  EXPECT_EQ(half.bodies[0].cloud.int3("cells"), (scene::Int3{5, 3, 3}));
  EXPECT_TRUE(half.integrator.reals("nested_levels").empty()) << "a level must not nest levels of its own";
  EXPECT_EQ(sw.scene.bodies[0].cloud.int3("cells"), (scene::Int3{10, 6, 6})) << "the scene itself is unchanged";
  EXPECT_EQ(scene::at_resolution(sw.scene, 0.01).bodies[0].cloud.int3("cells"), (scene::Int3{1, 1, 1}));

  const std::string shell = R"([scene]
name = "shell"
[integrator]
mode = "relax"
[[body]]
name = "cell"
[body.cloud]
generator = "shell"
face_cells = 32
layers = 5
[body.material]
model = "neo_hookean"
mu = 1000
lambda = 4000
[[body]]
name = "ball"
[body.cloud]
generator = "sphere"
center = [0, 0, 1e-5]
radius = 2e-6
cells = 16
[body.material]
model = "neo_hookean"
mu = 1000
lambda = 4000
)";
  const scene::Scene s = scene::parse_scene(shell, "shell.toml");
  const scene::Scene coarse = scene::at_resolution(s, 0.375);
  EXPECT_EQ(coarse.bodies[0].cloud.integer("face_cells"), 12);
  EXPECT_EQ(coarse.bodies[0].cloud.integer("layers"), 5) << "a shell keeps its layers: they are part of the model";
  EXPECT_EQ(coarse.bodies[1].cloud.integer("cells"), 6);
  EXPECT_EQ(scene::at_resolution(s, 0.01).bodies[0].cloud.integer("face_cells"), 2);
  EXPECT_EQ(scene::at_resolution(s, 0.01).bodies[1].cloud.integer("cells"), 2);
}

// The levels a relaxation runs: the scene's own factors while their coarsest level is
// small, halves of it before them when a refined scene would start on a large cloud.
TEST(NestedIteration, ARefinedSceneStartsOnACoarsestLevelOfAtMostTheCap) {
  const std::string rbc = testing::read_text(std::filesystem::path(RKPM_SOURCE_DIR) / "examples/rbc/rbc.toml");
  const auto at_face_cells = [&](int n) {
    std::string text = rbc;
    const std::string key = "face_cells = 32";
    text.replace(text.find(key), key.size(), "face_cells = " + std::to_string(n));
    return scene::parse_scene(text, "rbc.toml");
  };
  // The shipped cloud and the RBC study's finest (64:5): the scene's own levels, whose
  // coarsest holds 4,330 and 17,290 particles.
  EXPECT_EQ(nested_level_factors(at_face_cells(32)), (std::vector<double>{0.375, 0.625}));
  EXPECT_EQ(nested_level_factors(at_face_cells(64)), (std::vector<double>{0.375, 0.625}));
  // About 1e6 particles: 0.375 alone would start on 138,730; halved twice, on 8,680.
  const scene::Scene fine = at_face_cells(182);
  EXPECT_EQ(nested_level_factors(fine), (std::vector<double>{0.09375, 0.1875, 0.375, 0.625}));
  EXPECT_EQ(scene::at_resolution(fine, 0.09375).bodies[0].cloud.integer("face_cells"), 17);
  EXPECT_EQ(scene::at_resolution(fine, 0.1875).bodies[0].cloud.integer("face_cells"), 34);  // 34,690 > the cap
  // No levels declared: none added.
  EXPECT_TRUE(nested_level_factors(scene::parse_scene(block_scene("[]", false), "block.toml")).empty());
}

// The linear RK basis reproduces a linear field exactly, so a linear displacement of
// the coarse cloud arrives on the fine cloud exactly, whatever the two clouds are.
TEST(NestedIteration, CarryingTheStateReproducesALinearDisplacementField) {
  testing::ScopedThreads one(1);
  auto fine = testing::build_from_text(block_scene("[0.5]", false));
  auto coarse = build_world(scene::at_resolution(fine.scene, 0.5));
  const Mat3 A = (Mat3() << 0.02, -0.01, 0.005, 0.003, -0.015, 0.01, 0.0, 0.007, 0.012).finished();
  const Vec3 b(1e-3, -2e-3, 5e-4);
  Body& from = *coarse->bodies[0];
  for (std::size_t I = 0; I < from.size(); ++I) from.d[I] = A * from.cloud.X[I] + b;
  Body& to = *fine.world->bodies[0];
  to.constraints = EssentialBC();  // compare the carried field itself, before supports act
  ASSERT_GT(to.size(), 2 * from.size());
  const Transfer done = carry_state(*coarse, *fine.world);
  // A linear field needs no sweep: the interpolation rows reproduce it, to the rounding
  // of their float storage (1e-9 of the field here), below the sweeps' 1e-6 stop.
  EXPECT_EQ(done.sweeps, 0);
  EXPECT_LT(done.mismatch, 1e-7);
  double worst = 0.0;
  for (std::size_t J = 0; J < to.size(); ++J) {
    worst = std::max(worst, (to.d[J] - (A * to.cloud.X[J] + b)).norm());
    EXPECT_EQ(to.v[J], Vec3::Zero());
  }
  std::printf("linear field carried from %zu to %zu particles: worst error %.2e m\n", from.size(), to.size(), worst);
  EXPECT_LT(worst, 1e-13);
}

// The RK shape functions do not interpolate, so setting the finer cloud's generalized
// displacements to the coarser field's values would give it a smoothed copy of that
// field. carry_state matches the finer cloud's physical displacement to the coarser
// field at its particles instead: on a curved field the mismatch must be far below what
// the plain copy leaves (the plain copy is what this test measures as the reference).
TEST(NestedIteration, TheCarriedPhysicalDisplacementMatchesTheCoarseFieldAtTheFineParticles) {
  testing::ScopedThreads one(1);
  auto fine = testing::build_from_text(block_scene("[0.5]", false));
  auto coarse = build_world(scene::at_resolution(fine.scene, 0.5));
  const auto curved = [](const Vec3& X) {
    return Vec3(0.02 * X.x() * X.x(), -0.03 * X.y() * X.z(), 0.01 * std::sin(4.0 * X.x()) + 0.02 * X.y() * X.y());
  };
  Body& from = *coarse->bodies[0];
  for (std::size_t I = 0; I < from.size(); ++I) from.d[I] = curved(from.cloud.X[I]);
  Body& to = *fine.world->bodies[0];
  to.constraints = EssentialBC();

  // The coarser cloud's field at the finer particles, u_h(X_J) = sum_I Psi_I(X_J) d_I.
  const rk::RKApproximation from_rk = approximation(from);
  std::vector<Vec3> target(to.size(), Vec3::Zero());
  rk::ShapeValues sv;
  for (std::size_t J = 0; J < to.size(); ++J) {
    ASSERT_TRUE(from_rk.evaluate(to.cloud.X[J], sv, false));
    for (std::size_t k = 0; k < sv.ids.size(); ++k) target[J] += sv.psi[k] * from.d[sv.ids[k]];
  }
  double largest = 0.0, plain_copy = 0.0;
  for (std::size_t J = 0; J < to.size(); ++J) {
    largest = std::max(largest, target[J].norm());
    plain_copy = std::max(plain_copy, (rk::interpolate(to.interpolation, target, static_cast<Index>(J)) - target[J]).norm());
  }
  const Transfer done = carry_state(*coarse, *fine.world);
  std::vector<Vec3> u;
  physical_displacement(to, u);
  double matched = 0.0;
  for (std::size_t J = 0; J < to.size(); ++J) matched = std::max(matched, (u[J] - target[J]).norm());
  EXPECT_GT(done.sweeps, 0);
  EXPECT_NEAR(done.mismatch, matched / largest, 1e-3 * matched / largest) << "the report is the mismatch left";
  std::printf("curved field carried: largest %.3e, mismatch %.2e (plain copy %.2e)\n", largest, matched, plain_copy);
  EXPECT_GT(plain_copy, 1e-3 * largest) << "the field must be curved enough for the plain copy to miss it";
  EXPECT_LT(matched, 0.1 * plain_copy);  // measured: 1/31 of it
}

// The criterion for a faster route: its final displacements agree with a
// tight-tolerance FIRE run to 1e-3 of the largest displacement.
TEST(NestedIteration, NestedLevelsAndMassScalingReachThePlainFireEquilibrium) {
  testing::ScopedThreads one(1);
  const Relaxation plain = relax(block_scene("[]", false));
  const Relaxation nested = relax(block_scene("[0.5]", false));
  const Relaxation scaled = relax(block_scene("[]", true));
  const Relaxation both = relax(block_scene("[0.3, 0.6]", true));
  std::printf("steps on the 10x6x6 cloud: plain FIRE %lld; after a 5x3x3 level (%lld steps) %lld; mass scaling "
              "%lld; two levels (%lld steps) and mass scaling %lld\n",
              static_cast<long long>(plain.steps), static_cast<long long>(nested.coarse_steps),
              static_cast<long long>(nested.steps), static_cast<long long>(scaled.steps),
              static_cast<long long>(both.coarse_steps), static_cast<long long>(both.steps));
  ASSERT_TRUE(plain.converged && nested.converged && scaled.converged && both.converged);
  EXPECT_GT(nested.coarse_steps, 0);
  EXPECT_LT(relative_difference(nested.u, plain.u), 1e-3);
  EXPECT_LT(relative_difference(scaled.u, plain.u), 1e-3);
  EXPECT_LT(relative_difference(both.u, plain.u), 1e-3);
}

// examples/sag/sag.toml (a Mooney-Rivlin block clamped at its base, sagging under a
// body force) with its relaxation criteria (relax_force_tol 1e-5, relax_velocity_tol
// the default 1e-8) times `criteria_scale` and the route's keys.
std::string sag_scene(double criteria_scale, const std::string& levels, bool mass_scaling) {
  std::string text = testing::read_text(std::filesystem::path(RKPM_SOURCE_DIR) / "examples/sag/sag.toml");
  const std::string criterion = "relax_force_tol = 1e-5\n";
  const auto at = text.find(criterion);
  if (at == std::string::npos) throw std::runtime_error("examples/sag/sag.toml: no '" + criterion + "'");
  std::ostringstream keys;
  keys << "relax_force_tol = " << 1e-5 * criteria_scale << "\nrelax_velocity_tol = " << 1e-8 * criteria_scale
       << "\nnested_levels = " << levels << "\nmass_scaling = " << (mass_scaling ? "true" : "false") << "\n";
  return text.replace(at, criterion.size(), keys.str());
}

// The same-equilibrium criterion on the sag scene: a coarser level first and mass
// scaling, at the scene's criteria, stop within 1e-3 of the largest displacement of
// plain FIRE at ten times tighter criteria.
TEST(NestedIteration, TheSagSceneReachesTheSameRestByEveryRoute) {
  testing::ScopedThreads one(1);
  const Relaxation rest = relax(sag_scene(0.1, "[]", false));
  const Relaxation plain = relax(sag_scene(1.0, "[]", false));
  const Relaxation route = relax(sag_scene(1.0, "[0.5]", true));
  std::printf("sag: plain FIRE at ten times tighter criteria %lld steps; at the scene's %lld steps, %.2e apart; a "
              "5x5x2 level (%lld steps) and mass scaling %lld steps, %.2e apart\n",
              static_cast<long long>(rest.steps), static_cast<long long>(plain.steps),
              relative_difference(plain.u, rest.u), static_cast<long long>(route.coarse_steps),
              static_cast<long long>(route.steps), relative_difference(route.u, rest.u));
  ASSERT_TRUE(rest.converged && plain.converged && route.converged);
  EXPECT_GT(route.coarse_steps, 0);
  EXPECT_LT(relative_difference(plain.u, rest.u), 1e-3);
  EXPECT_LT(relative_difference(route.u, rest.u), 1e-3);
}

// FIRE to the scene's criteria, then the Newton-Krylov finish (relax_finish =
// "newton_krylov") to `finish_tol`: the displacements at FIRE's stop and after the finish.
struct Finished {
  std::vector<Vec3> fire_u, newton_u;
  NewtonKrylovReport report;
  double residual = 0.0;  // the integrator's measure after the finish
  double ledger_error_at_stop = 0.0, ledger_error_after = 0.0;  // EnergyLedger::relative_error
};

Finished relax_then_finish(const std::string& toml, double finish_tol) {
  auto sw = testing::build_from_text(toml);
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  while (sw.world->step < 200000 && !integrator.converged()) integrator.step();
  Finished f;
  physical_displacement(*sw.world->bodies.front(), f.fire_u);
  NewtonKrylovSettings newton = sw.settings.newton;
  newton.force_tol = finish_tol;
  f.ledger_error_at_stop = integrator.measure_energy().relative_error();
  f.report = integrator.finish_newton_krylov(newton);
  f.ledger_error_after = integrator.measure_energy().relative_error();
  f.residual = integrator.residual();
  physical_displacement(*sw.world->bodies.front(), f.newton_u);
  return f;
}

// The finish from FIRE's stop on the sag scene (a dead load, no director: the
// difference Jacobian is the tangent, so Newton converges quadratically) reaches a
// residual 1e5 times below the scene's criterion in a few Newton steps (measured 3:
// 7.3e-7, 7.6e-9, 5.4e-13), and lands within 1e-3 of the largest displacement of plain
// FIRE at ten times tighter criteria, nearer to it than FIRE's own stop.
TEST(NewtonKrylov, FinishesTheSagSceneWhereTighterFireComesToRest) {
  testing::ScopedThreads one(1);
  const Relaxation rest = relax(sag_scene(0.1, "[]", false));
  const Finished f = relax_then_finish(sag_scene(1.0, "[]", false), 1e-10);
  const double newton_apart = relative_difference(f.newton_u, rest.u);
  const double fire_apart = relative_difference(f.fire_u, rest.u);
  std::printf("sag: Newton-Krylov finish %d Newton steps, %lld GMRES iterations, %lld force evaluations, residual "
              "%.1e; from plain FIRE at ten times tighter criteria %.2e apart (FIRE's stop %.2e)\n",
              f.report.newton_steps, static_cast<long long>(f.report.krylov_iterations),
              static_cast<long long>(f.report.force_evaluations), f.report.residual, newton_apart, fire_apart);
  ASSERT_TRUE(rest.converged);
  EXPECT_TRUE(f.report.converged) << f.report.stop;
  EXPECT_LT(f.residual, 1e-10);
  EXPECT_LE(f.report.newton_steps, 5);
  for (std::size_t k = 1; k < f.report.residuals.size(); ++k)
    EXPECT_LT(f.report.residuals[k], 0.1 * f.report.residuals[k - 1]) << "Newton step " << k + 1;
  EXPECT_LT(newton_apart, 1e-3);
  EXPECT_LT(newton_apart, fire_apart);
  // The ledger books the finish (the kinetic energy FIRE left, the load's work, the rest
  // as dissipation): its balance is what it was at FIRE's stop.
  EXPECT_NEAR(f.ledger_error_after, f.ledger_error_at_stop, 1e-3 * f.ledger_error_at_stop);
}

// The block on rollers under a follower pressure (a nonsymmetric tangent, which GMRES
// takes as it comes): the finish reaches a residual of 1e-12 mu, and FIRE's stop at its
// tight 1e-7 mu is within ten times its measured distance (2.5e-6) of it.
TEST(NewtonKrylov, FinishesTheBlockUnderFollowerPressure) {
  testing::ScopedThreads one(1);
  const Finished f = relax_then_finish(block_scene("[]", false), 1e-12);
  const double apart = relative_difference(f.newton_u, f.fire_u);
  std::printf("10x6x6 block: Newton-Krylov finish %d Newton steps, %lld GMRES iterations, %lld force evaluations, "
              "residual %.1e, %.2e from FIRE's stop\n",
              f.report.newton_steps, static_cast<long long>(f.report.krylov_iterations),
              static_cast<long long>(f.report.force_evaluations), f.report.residual, apart);
  EXPECT_TRUE(f.report.converged) << f.report.stop;
  EXPECT_LT(f.residual, 1e-12);
  EXPECT_LT(apart, 2.5e-5);  // FIRE's own stop at 1e-7 mu: measured 2.5e-6
}

// FIRE 2.0 (Guenole et al. 2020), whose uphill steps move the particles back by half a
// step before they stop, reaches the same equilibrium as plain FIRE.
TEST(Fire2, ReachesThePlainFireEquilibrium) {
  testing::ScopedThreads one(1);
  const Relaxation plain = relax(block_scene("[]", false));
  auto sw = testing::build_from_text(block_scene("[]", false, "fire2"));
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  while (sw.world->step < 200000 && !integrator.converged()) integrator.step();
  std::vector<Vec3> u;
  physical_displacement(*sw.world->bodies.front(), u);
  std::printf("10x6x6 block: plain FIRE %lld steps; FIRE 2.0 %lld steps with %lld step-backs; difference %.2e of "
              "the largest displacement\n",
              static_cast<long long>(plain.steps), static_cast<long long>(sw.world->step),
              static_cast<long long>(integrator.step_backs()), relative_difference(u, plain.u));
  ASSERT_TRUE(plain.converged && integrator.converged());
  EXPECT_GT(integrator.step_backs(), 0);
  EXPECT_LT(relative_difference(u, plain.u), 1e-3);
}

// Mass scaling lifts every particle's own step to the median and leaves the others.
TEST(MassScaling, EveryParticleReachesTheMedianStepAndNoneGetsLighter) {
  testing::ScopedThreads one(1);
  auto sw = testing::build_from_text(block_scene("[]", true));
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  const Body& b = *sw.world->bodies[0];
  std::vector<double> steps;
  particle_wave_steps(b, steps);
  std::vector<double> sorted = steps;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const double median = sorted[sorted.size() / 2];
  std::size_t unchanged = 0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    ASSERT_GE(b.inertia[i], b.mass[i]);
    if (b.inertia[i] == b.mass[i]) {
      ++unchanged;
      EXPECT_GE(steps[i], median);
    } else {
      EXPECT_NEAR(steps[i] * std::sqrt(b.inertia[i] / b.mass[i]), median, 1e-12 * median);
    }
  }
  EXPECT_GE(unchanged, b.size() / 2);
  EXPECT_NEAR(material_stable_dt(b), median, 1e-12 * median);
  EXPECT_GT(integrator.stable_dt(), integrator.unscaled_stable_dt());
}

}  // namespace
}  // namespace rkpm::sim
