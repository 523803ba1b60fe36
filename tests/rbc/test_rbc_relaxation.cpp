// The red-blood-cell relaxation (seed section 4.1) on a coarse shell: the driver of
// examples/rbc/rbc.toml (active stress, seed Eq. 1: contractile in the inner half of
// the faces, extensile in the outer half of the rim, plus water loss of the cytoplasm)
// turns the oblate shell into a biconcave disc close to Evans-Fung, and the same shell
// without the driver stays where it started.
#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/build.hpp"
#include "rkpm/sim/history.hpp"
#include "rkpm/sim/integrator.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <string>

namespace {

using rkpm::sim::ShapeReport;

// The default scene's physics at face_cells 12, layers 3 (2,598 particles). The
// driver keys are parameters so that the control is the same text without them.
// criteria_scale multiplies both relaxation criteria (1e-4 mu, 1e-8).
std::string coarse_scene(const std::string& activity, double target, double thickness = 0.5e-6,
                         double criteria_scale = 1.0) {
  return fmt::format(R"(
[scene]
name = "rbc_coarse"
[integrator]
mode = "relax"
relax_force_tol = {}
relax_velocity_tol = {}
contact_mass_scaling = true
[[body]]
name = "cell"
density = 1000.0
[body.cloud]
generator = "shell"
semi_axes = [5e-6, 5e-6, 1.5e-6]
thickness = {}
face_cells = 12
layers = 3
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
                     1e-4 * criteria_scale, 1e-8 * criteria_scale, thickness, activity, target);
}

struct Relaxed {
  ShapeReport initial, final;
  double max_displacement = 0.0;  // max |x - X| over the particles [m]
  std::vector<rkpm::Vec3> displacement;  // generalized displacements d at the end
  bool converged = false;
};

Relaxed relax(const std::string& text) {
  const auto scene = rkpm::scene::parse_scene(text, "rbc_coarse.toml");
  auto world = rkpm::sim::build_world(scene);
  auto& body = *world->bodies.front();
  Relaxed out;
  out.initial = rkpm::sim::final_shape(body);
  rkpm::sim::Integrator integrator(*world, rkpm::sim::integrator_settings(scene));
  integrator.initialize();
  for (int step = 0; step < 20000; ++step) {
    integrator.step();
    if (integrator.converged()) {
      out.converged = true;
      break;
    }
  }
  out.final = rkpm::sim::final_shape(body);
  for (const auto& d : body.d) out.max_displacement = std::max(out.max_displacement, d.norm());
  out.displacement = body.d;
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
  // at about 0.65, the default one at about 0.58-0.61).
  EXPECT_LT(r.final.diameter, largest_diameter_ratio * r.initial.diameter);
  EXPECT_GT(r.final.reduced_volume, 0.55);
  EXPECT_LT(r.final.reduced_volume, 0.68);
  // The run's own verdict on the four criteria above.
  EXPECT_TRUE(r.final.matches_evans_fung);
}

// The default scene's coarse shell relaxed once and shared by the tests that read it
// (about 150 s under the sanitizers).
const Relaxed& default_disc() {
  static const Relaxed relaxed = relax(coarse_scene(kDriver, 0.9));
  return relaxed;
}

TEST(RedBloodCell, ActiveWallWithWaterLossTurnsTheShellIntoAnEvansFungDisc) {
  expect_evans_fung_disc(default_disc());
}

// The seed's other wall thickness, "about 0.3 um", with the same driver keys: the
// bending part of the layer activity follows T / zeta_reference_thickness (measured
// with the director relaxing, mobility = 1e3: 0.43 here, 0.49 without the scaling)
// and the rim's amplitude falls to 0.67 of the 0.5 um wall's (zeta_rim_fold_share).
TEST(RedBloodCell, TheSameDriverHoldsTheDiscAtTheSeedsThinnerWall) {
  constexpr double seed_wall_thickness = 0.3e-6;  // [m]
  const Relaxed r = relax(coarse_scene(kDriver, 0.9, seed_wall_thickness));
  expect_evans_fung_disc(r);
  // The wall on the axis ends thinner than it started (the contractile inner half
  // squeezes it).
  EXPECT_LT(r.final.wall_thickness_centre, seed_wall_thickness);
}

// The director is carried by the wall (mobility = 0), so the relaxation's stop is a
// state at rest: ten times tighter criteria move it by 4.6e-4 of the largest
// displacement (the relaxation issue's bound for the same equilibrium is 1e-3). With
// the director relaxing (mobility = 1e3) this shell's stop is 1.4e-2 from its rest,
// h_min/h_max 0.459 against 0.452, and the default cloud's faces crept apart long
// after the scene's stop (docs/relaxation.md, "The director carried by the wall").
// A wall 1.5 times the seed's T with the same driver keys: zeta_rim_fold_share doubles
// the rim's activity to hold the thicker wall's fold open. Measured: h_min/h_max 0.485,
// RMS 4.3 % of D, D 9.80 um from 10 um (the thick wall shrinks less than the others:
// hence 0.99). Without the share (zeta_rim_fold_share = 0) the same shell ends at 0.543,
// RMS 6.3 %, D 10.16 um: not biconcave.
TEST(RedBloodCell, TheSameDriverHoldsTheDiscAtAThickerWall) {
  const Relaxed r = relax(coarse_scene(kDriver, 0.9, 0.75e-6));
  expect_evans_fung_disc(r, 0.99);
}

TEST(RedBloodCell, TheDiscIsAtRestWhereTheRelaxationStops) {
  const Relaxed& stop = default_disc();
  const Relaxed rest = relax(coarse_scene(kDriver, 0.9, 0.5e-6, 0.1));
  ASSERT_TRUE(stop.converged);
  ASSERT_TRUE(rest.converged);
  ASSERT_EQ(stop.displacement.size(), rest.displacement.size());
  double largest_difference = 0.0;
  for (std::size_t i = 0; i < stop.displacement.size(); ++i)
    largest_difference = std::max(largest_difference, (stop.displacement[i] - rest.displacement[i]).norm());
  EXPECT_LT(largest_difference, 1e-3 * rest.max_displacement);
  EXPECT_NEAR(stop.final.h_min / stop.final.h_max, rest.final.h_min / rest.final.h_max, 2e-3);
}

TEST(RedBloodCell, WithoutDriverTheShellStaysWhereItStarted) {
  const Relaxed r = relax(coarse_scene("", 1.0));
  ASSERT_TRUE(r.converged);
  // The reference shell is stress-free up to the Frank energy of its curved
  // director field (Eq. 2), which moves it by about 4e-4 of the diameter; the
  // driven run moves it by about 0.1 D. The shape metrics stay.
  EXPECT_LT(r.max_displacement, 1e-3 * r.initial.diameter);
  EXPECT_NEAR(r.final.h_min / r.final.h_max, r.initial.h_min / r.initial.h_max, 1e-3);
  EXPECT_NEAR(r.final.reduced_volume, r.initial.reduced_volume, 1e-3);
  EXPECT_NEAR(r.final.diameter, r.initial.diameter, 1e-4 * r.initial.diameter);
}

}  // namespace
