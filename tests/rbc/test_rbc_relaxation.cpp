// The red-blood-cell relaxation (seed section 4.1) on a coarse shell: the driver of
// examples/rbc/rbc.toml (active stress, seed Eq. 1: contractile in the inner half of
// the faces, extensile in the outer half of the rim, plus water loss of the cytoplasm)
// turns the oblate shell into a biconcave disc close to Evans-Fung, and the same shell
// without the driver stays where it started.
#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/build.hpp"
#include "rkpm/sim/history.hpp"
#include "rkpm/sim/integrator.hpp"
#include "rkpm/sim/nested_iteration.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <string>

namespace {

using rkpm::sim::ShapeReport;

// The default scene's physics, step (dt_safety 0.9) and stabilization (0.1 at the
// 0.5 um wall, scaled as (T / 0.5 um)^2 at another) at face_cells 12, layers 3
// (2,598 particles). The driver keys are parameters so that the control is the same text without them.
// criteria_scale multiplies both relaxation criteria (1e-4 mu, 1e-8); nested_levels is
// the TOML list of [integrator] nested_levels.
std::string coarse_scene(const std::string& activity, double target, double thickness = 0.5e-6,
                         double criteria_scale = 1.0, const std::string& nested_levels = "[]") {
  return fmt::format(R"(
[scene]
name = "rbc_coarse"
[integrator]
mode = "relax"
relax_force_tol = {}
relax_velocity_tol = {}
nested_levels = {}
contact_mass_scaling = true
dt_safety = 0.9
[[body]]
name = "cell"
density = 1000.0
[body.cloud]
generator = "shell"
semi_axes = [5e-6, 5e-6, 1.5e-6]
thickness = {}
face_cells = 12
layers = 3
[body.rk]
stabilization_reference_thickness = 0.5e-6
[body.material]
model = "lce"
mu = 1e4
bulk = 1e5
s = 2.0
kappa = 1e-11
mobility = 0.0
{}
[body.director]
initial = "surface_normal"
boundary = "normal"
[[term]]
type = "volume_constraint"
body = "cell"
surface = "inner"
bulk = 1e6
target = {}
[[term]]
type = "wall_contact"
body = "cell"
surface = "inner"
distance = 0.2e-6
pressure = 1e4
)",
                     1e-4 * criteria_scale, 1e-8 * criteria_scale, nested_levels, thickness, activity, target);
}

struct Relaxed {
  ShapeReport initial, final;
  double max_displacement = 0.0;  // max |x - X| over the particles [m]
  std::vector<rkpm::Vec3> displacement;  // generalized displacements d at the end
  std::vector<rkpm::Vec3> reference;     // the particles' reference positions X
  bool converged = false;
  std::int64_t level_steps = 0;  // on the coarser clouds of nested_levels
  std::int64_t steps = 0;        // on the shell itself
  // Where the same run comes to rest under tighter criteria (relax's rest_criteria_scale).
  std::vector<rkpm::Vec3> rest_displacement;
  std::int64_t rest_steps = 0;
  bool rest_converged = false;
  // Where the Newton-Krylov finish takes the run from its stop (relax's newton_tol).
  std::vector<rkpm::Vec3> newton_displacement;
  rkpm::sim::NewtonKrylovReport newton;
  ShapeReport newton_final;
};

// Relaxes `settings` until converged() (at most 20,000 steps); true if it did.
bool relax_until_converged(rkpm::sim::World& world, const rkpm::sim::IntegratorSettings& settings) {
  rkpm::sim::Integrator integrator(world, settings);
  integrator.initialize();
  for (int step = 0; step < 20000; ++step) {
    integrator.step();
    if (integrator.converged()) return true;
  }
  return false;
}

// The Newton-Krylov finish (relax_finish = "newton_krylov") from the world's state to a
// residual below `tol`.
rkpm::sim::NewtonKrylovReport finish_exactly(rkpm::sim::World& world, const rkpm::sim::IntegratorSettings& settings,
                                            double tol) {
  rkpm::sim::Integrator integrator(world, settings);
  integrator.initialize();
  rkpm::sim::NewtonKrylovSettings finish = settings.newton;
  finish.force_tol = tol;
  return integrator.finish_newton_krylov(finish);
}

// Relaxes the scene `text` by its route (its nested levels first, if it declares any).
// With `rest_criteria_scale` > 0 the run then goes on from its stop with both criteria
// multiplied by it, and `rest_displacement` holds where it comes to rest. With
// `newton_tol` > 0 the Newton-Krylov finish then goes on from there, and
// `newton_displacement` holds where it ends.
Relaxed relax(const std::string& text, double rest_criteria_scale = 0.0, double newton_tol = 0.0) {
  const auto scene = rkpm::scene::parse_scene(text, "rbc_coarse.toml");
  auto world = rkpm::sim::build_world(scene);
  auto& body = *world->bodies.front();
  Relaxed out;
  out.initial = rkpm::sim::final_shape(body);
  std::ostringstream level_log;
  for (const auto& level : rkpm::sim::relax_coarse_levels(scene, *world, level_log)) out.level_steps += level.steps;
  auto settings = rkpm::sim::integrator_settings(scene);
  out.converged = relax_until_converged(*world, settings);
  out.final = rkpm::sim::final_shape(body);
  for (const auto& d : body.d) out.max_displacement = std::max(out.max_displacement, d.norm());
  out.displacement = body.d;
  out.reference = body.cloud.X;
  out.steps = world->step;
  if (rest_criteria_scale > 0.0 && out.converged) {
    settings.relax_force_tol *= rest_criteria_scale;
    settings.relax_velocity_tol *= rest_criteria_scale;
    out.rest_converged = relax_until_converged(*world, settings);
    out.rest_displacement = body.d;
    out.rest_steps = world->step - out.steps;
  }
  if (newton_tol > 0.0 && out.converged) {
    out.newton = finish_exactly(*world, settings, newton_tol);
    out.newton_displacement = body.d;
    out.newton_final = rkpm::sim::final_shape(body);
  }
  return out;
}

// The driver keys of examples/rbc/rbc.toml.
const char* const kDriver = R"(zeta = -1e4
zeta_profile = "radial"
zeta_power = 1
zeta_layer = "inner"
zeta_rim = 3e4
zeta_rim_power = 2
zeta_rim_layer = "outer"
zeta_reference_thickness = 0.5e-6
zeta_rim_fold_share = 0.421)";

// The shape criteria of the scene, on the coarse shell.
// `largest_diameter_ratio` bounds the final over the initial diameter.
void expect_evans_fung_disc(const Relaxed& r, double largest_diameter_ratio = 0.97) {
  ASSERT_TRUE(r.converged);
  // The oblate start is convex: thickest at the centre.
  EXPECT_NEAR(r.initial.h_min / r.initial.h_max, 1.0, 0.02);
  // Biconcave: a central dimple (Evans-Fung: 0.316; the criterion of the scene is 0.5)
  // with the thickest ring off the axis (Evans-Fung: 0.70 R).
  EXPECT_LT(r.final.h_min / r.final.h_max, 0.5);
  EXPECT_GT(r.final.r_hmax_over_R, 0.55);
  EXPECT_LT(r.final.r_hmax_over_R, 0.85);
  // Both faces dimple alike: not a cup (stomatocyte).
  EXPECT_LT(r.final.updown_asymmetry, 0.05);
  // The dimple leaves fluid between the faces (they have not passed through each other).
  EXPECT_FALSE(r.final.walls_crossed);
  EXPECT_GT(r.final.inner_gap_centre, 0.0);
  // The thickness profile is close to Evans-Fung scaled to the same diameter (the scene's
  // criterion is 5 % of D; the oblate start is about 12 % of D away).
  EXPECT_GT(r.initial.rms_vs_evans_fung, 0.08);
  EXPECT_LT(r.final.rms_vs_evans_fung, 0.05);
  // The diameter shrinks (the rim's outer half contracts in-plane) and the reduced
  // volume stays near the discocyte range (Evans-Fung 0.644; this coarse shell ends
  // at about 0.65, the default one at about 0.62).
  EXPECT_LT(r.final.diameter, largest_diameter_ratio * r.initial.diameter);
  EXPECT_GT(r.final.reduced_volume, 0.55);
  EXPECT_LT(r.final.reduced_volume, 0.68);
  // The run's own verdict on the four criteria above.
  EXPECT_TRUE(r.final.matches_evans_fung);
}

// The two tests that relax the coarse RBC twice and finish it by Newton-Krylov steps
// run past the suite's per-test limit in the sanitizer build (AddressSanitizer at -O1),
// since the coarse level's faces meet, which makes that level long: they are labelled
// sanitizer-skipped (tests/rbc/CMakeLists.txt). The sanitizer build runs the other
// three RBC relaxations, which go through the same nested level, wall contact and
// volume constraint, and tests/sim the Newton-Krylov finish; the Release build runs
// all five.

// The route of examples/rbc/rbc.toml: the scene relaxed first on a coarser copy of
// itself (face_cells 9), its state carried to the shell (nested iteration). Before the
// middle layer carried half of each half-wall activity (docs/verification/rbc.md), a level at
// face_cells 6 led this shell to another, deeper rest state (h_min/h_max 0.385 against
// 0.439 from the reference state): the coarsest level must still hold the disc.
const char* const kNestedLevels = "[0.75]";

// The default scene's coarse shell relaxed by the scene's route.
Relaxed default_disc(double rest_criteria_scale = 0.0, double newton_tol = 0.0) {
  return relax(coarse_scene(kDriver, 0.9, 0.5e-6, 1.0, kNestedLevels), rest_criteria_scale, newton_tol);
}

// max_I |a_I - b_I - (t + w x (X_I - c))| of the generalized displacements, with t and
// w the (linearised) rigid motion that fits a - b best in the least-squares sense and
// c the particles' centroid: the shell floats free, so its
// equilibrium is defined up to a rigid motion, which a route may carry in from a coarser
// cloud (the RK approximation reproduces linear fields, so a rigid motion of the
// displacements is one of the generalized displacements too).
double largest_difference(const std::vector<rkpm::Vec3>& a, const std::vector<rkpm::Vec3>& b,
                          const std::vector<rkpm::Vec3>& reference) {
  const std::size_t n = b.size();
  rkpm::Vec3 centre = rkpm::Vec3::Zero(), mean = rkpm::Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    centre += reference[i];
    mean += a[i] - b[i];
  }
  centre /= static_cast<double>(n);
  mean /= static_cast<double>(n);
  // w from sum_I r_I x (e_I - w x r_I) = 0, e_I the difference less its mean.
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  rkpm::Vec3 moment = rkpm::Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const rkpm::Vec3 r = reference[i] - centre;
    inertia += r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose();
    moment += r.cross(a[i] - b[i] - mean);
  }
  const rkpm::Vec3 w = inertia.ldlt().solve(moment);
  double largest = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    largest = std::max(largest, (a[i] - b[i] - mean - w.cross(reference[i] - centre)).norm());
  return largest;
}

// largest_difference over max_I |b_I|.
double relative_difference(const std::vector<rkpm::Vec3>& a, const std::vector<rkpm::Vec3>& b,
                           const std::vector<rkpm::Vec3>& reference) {
  double largest = 0.0;
  for (const auto& x : b) largest = std::max(largest, x.norm());
  return largest_difference(a, b, reference) / largest;
}

// The scene's route ends in the disc, and at rest: the director is carried by the wall
// (mobility = 0), and the run continued from its stop with ten times tighter criteria
// moves by 8.7e-7 of the largest displacement (7.4e-4 before the middle layer carried
// half of each half-wall activity, docs/verification/rbc.md; the bound for the same equilibrium is
// 1e-3). With the director relaxing (mobility =
// 1e3) and plain FIRE this shell's stop was 1.4e-2 from its rest, and the default
// cloud's faces crept apart long after the scene's stop (docs/verification/relaxation.md, "The
// director carried by the wall").
// The Newton-Krylov finish (relax_finish = "newton_krylov") from there drives the
// residual to 1e-9 mu, 1e5 times below the scene's criterion, in a few Newton steps
// with the director carried in every evaluation (measured from the rest: 6 steps, 1,764
// force evaluations, residual 7.7e-10): the exact rest state, which the route's stop
// and the tighter run's rest are within 1e-3 of (the bound for the same equilibrium;
// measured 2.9e-5 and 2.8e-5).
TEST(RedBloodCell, ActiveWallWithWaterLossTurnsTheShellIntoAnEvansFungDiscAtRest) {
  const Relaxed r = default_disc(0.1, 1e-9);
  expect_evans_fung_disc(r);
  ASSERT_TRUE(r.rest_converged);
  const double moved = relative_difference(r.displacement, r.rest_displacement, r.reference);
  std::printf("coarse RBC, the scene's route: %lld + %lld steps to its stop, %lld more to rest under ten times "
              "tighter criteria, which move it by %.2e of the largest displacement\n",
              static_cast<long long>(r.level_steps), static_cast<long long>(r.steps),
              static_cast<long long>(r.rest_steps), moved);
  EXPECT_GT(r.level_steps, 0);
  EXPECT_LT(moved, 1e-3);
  const double stop_to_exact = relative_difference(r.displacement, r.newton_displacement, r.reference);
  const double rest_to_exact = relative_difference(r.rest_displacement, r.newton_displacement, r.reference);
  std::printf("the Newton-Krylov finish from that rest: %d Newton steps, %lld force evaluations, residual %.1e; the "
              "stop %.2e and the rest %.2e from where it ends\n",
              r.newton.newton_steps, static_cast<long long>(r.newton.force_evaluations), r.newton.residual,
              stop_to_exact, rest_to_exact);
  EXPECT_TRUE(r.newton.converged) << r.newton.stop;
  EXPECT_LT(r.newton.residual, 1e-9);
  EXPECT_LE(r.newton.newton_steps, 8);
  EXPECT_LT(stop_to_exact, 1e-3);
  EXPECT_LT(rest_to_exact, 1e-3);
}

// The seed's other wall thickness, "about 0.3 um", with the same driver keys: the
// bending part of the layer activity follows T / zeta_reference_thickness (measured
// with the director relaxing, mobility = 1e3: 0.43 here, 0.49 without the scaling)
// and the rim's amplitude falls to 0.67 of the 0.5 um wall's (zeta_rim_fold_share).
// This thin coarse wall shrinks least, hence 0.98: with the stabilization scaled to the
// wall (0.036) it ends at h_min/h_max 0.348, RMS 3.86 % of D, D 9.59 um; with 0.1 at
// every thickness 0.332, 4.55 %, D 9.70 um, and with 0.3 it leaves the criteria (RMS
// 5.49 %, D 9.88 um: docs/theory/numerics.md, "Walls of another thickness").
TEST(RedBloodCell, TheSameDriverHoldsTheDiscAtTheSeedsThinnerWall) {
  constexpr double seed_wall_thickness = 0.3e-6;  // [m]
  const Relaxed r = relax(coarse_scene(kDriver, 0.9, seed_wall_thickness, 1.0, kNestedLevels));
  std::printf("coarse RBC at 0.3 um: h_min/h_max %.4f, RMS against Evans-Fung %.4f of D, D %.3e m\n",
              r.final.h_min / r.final.h_max, r.final.rms_vs_evans_fung, r.final.diameter);
  expect_evans_fung_disc(r, 0.98);
  // The wall on the axis ends thinner than it started (the contractile inner half
  // squeezes it).
  EXPECT_LT(r.final.wall_thickness_centre, seed_wall_thickness);
}

// A wall 1.5 times the seed's T with the same driver keys: zeta_rim_fold_share doubles
// the rim's activity to hold the thicker wall's fold open. Measured with the
// stabilization scaled to the wall (0.225): h_min/h_max 0.462, RMS 3.84 % of D, D 9.42
// um; with 0.1: 0.470, RMS 3.93 % of D, D 9.48 um from 10 um (before the middle layer carried half of each
// half-wall activity, docs/verification/rbc.md: 0.485, 4.26 %, D 9.80 um, the thick wall shrinking
// least: hence 0.99). Before that fix, without the share (zeta_rim_fold_share = 0) the
// same shell ended at 0.543, RMS 6.3 %, D 10.16 um: not biconcave. Plain FIRE from the start (with 0.1): through
// the nested level at face_cells 9 this thick coarse wall ends just outside the criteria (RMS
// 5.06 %, D 9.94 um), where the 30,730-particle scene's levels hold it (docs/verification/rbc.md).
TEST(RedBloodCell, TheSameDriverHoldsTheDiscAtAThickerWall) {
  const Relaxed r = relax(coarse_scene(kDriver, 0.9, 0.75e-6));
  std::printf("coarse RBC at 0.75 um: h_min/h_max %.4f, RMS against Evans-Fung %.4f of D, D %.3e m\n",
              r.final.h_min / r.final.h_max, r.final.rms_vs_evans_fung, r.final.diameter);
  expect_evans_fung_disc(r, 0.99);
}

// Plain FIRE from the reference state comes to rest in a neighbouring state, not the
// same one: the two rest states are 3.2e-2 of the largest displacement apart (rigid
// motion removed; 5.5e-2 before the middle layer carried half of each half-wall
// activity, docs/verification/rbc.md), and each stays where it is under ten times tighter criteria.
// Both are biconcave by the scene's criteria with the same shape to 1e-4 in h_min/h_max
// (0.3414 and 0.3415; 0.4366 and 0.4397 before) and 1e-4 of D in RMS against Evans-Fung
// (3.39 and 3.40 %); how close within the family depends on the path (docs/verification/relaxation.md).
// The bounds would catch a route that lands on another branch: before the fix, with a
// coarse level at face_cells 6, the route ended at h_min/h_max 0.385 against 0.439,
// 9.4e-2 apart (docs/verification/relaxation.md, "Which rest state a route reaches").
// The Newton-Krylov finish from each stop confirms it: both end at a residual below
// 1e-9 mu, 3.23e-2 apart, in the same shape (h_min/h_max 0.3414 and 0.3415): two exact
// rest states.
TEST(RedBloodCell, PlainFireFromTheStartRestsInTheSameShape) {
  const Relaxed route = default_disc(0.0, 1e-9);
  const Relaxed plain = relax(coarse_scene(kDriver, 0.9, 0.5e-6, 0.1), 0.0, 1e-9);
  ASSERT_TRUE(route.converged);
  ASSERT_TRUE(plain.converged);
  ASSERT_EQ(route.displacement.size(), plain.displacement.size());
  const double apart = relative_difference(route.displacement, plain.displacement, plain.reference);
  std::printf("coarse RBC at rest: the scene's route and plain FIRE are %.2e of the largest displacement apart; "
              "h_min/h_max %.4f and %.4f, RMS against Evans-Fung %.4f and %.4f of D\n",
              apart, route.final.h_min / route.final.h_max, plain.final.h_min / plain.final.h_max,
              route.final.rms_vs_evans_fung, plain.final.rms_vs_evans_fung);
  expect_evans_fung_disc(plain);
  EXPECT_LT(apart, 0.08);
  EXPECT_NEAR(route.final.h_min / route.final.h_max, plain.final.h_min / plain.final.h_max, 5e-3);
  EXPECT_NEAR(route.final.rms_vs_evans_fung, plain.final.rms_vs_evans_fung, 4e-3);
  EXPECT_NEAR(route.final.diameter, plain.final.diameter, 1e-3 * plain.final.diameter);
  const double exact_apart = relative_difference(route.newton_displacement, plain.newton_displacement, plain.reference);
  std::printf("their Newton-Krylov finishes: residual %.1e and %.1e, %.2e of the largest displacement apart; "
              "h_min/h_max %.4f and %.4f\n",
              route.newton.residual, plain.newton.residual, exact_apart,
              route.newton_final.h_min / route.newton_final.h_max, plain.newton_final.h_min / plain.newton_final.h_max);
  EXPECT_LT(route.newton.residual, 1e-9);
  EXPECT_LT(plain.newton.residual, 1e-9);
  EXPECT_GT(exact_apart, 1e-2) << "the two rest states met: docs/verification/relaxation.md says they are two";
  EXPECT_NEAR(route.newton_final.h_min / route.newton_final.h_max,
              plain.newton_final.h_min / plain.newton_final.h_max, 5e-3);
}

TEST(RedBloodCell, WithoutDriverTheShellStaysWhereItStarted) {
  const Relaxed r = relax(coarse_scene("", 1.0), 0.1);
  ASSERT_TRUE(r.converged);
  ASSERT_TRUE(r.rest_converged);
  // The reference shell is stress-free up to the Frank energy of its curved
  // director field (Eq. 2), which moves it by about 2e-4 of the diameter; the
  // driven run moves it by about 0.1 D. The shape metrics stay.
  EXPECT_LT(r.max_displacement, 1e-3 * r.initial.diameter);
  EXPECT_NEAR(r.final.h_min / r.final.h_max, r.initial.h_min / r.initial.h_max, 1e-3);
  EXPECT_NEAR(r.final.reduced_volume, r.initial.reduced_volume, 1e-3);
  EXPECT_NEAR(r.final.diameter, r.initial.diameter, 1e-4 * r.initial.diameter);
  // And it is at rest where it stops: ten times tighter criteria move it by less than
  // 1e-4 of the diameter (measured: 2.5e-10 m, 2.5e-5 D; the driven shell's largest
  // displacement is 9.3e-7 m, so this is 2.7e-4 of that). The control's own
  // displacement (2e-9 m of Frank-energy sag) is below what the scene's force criterion
  // resolves, so it is not the scale.
  const double moved = largest_difference(r.displacement, r.rest_displacement, r.reference);
  std::printf("coarse RBC control: %lld steps, %lld more under ten times tighter criteria, which move it by %.2e m\n",
              static_cast<long long>(r.steps), static_cast<long long>(r.rest_steps), moved);
  EXPECT_LT(moved, 1e-4 * r.initial.diameter);
}

}  // namespace
