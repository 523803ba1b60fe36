// A coarse unstructured tetrahedral cloud with a fixed face (issue: a Gmsh box of
// 10 x 10 x 4 um, base fixed, gentle gravity, went unstable at mesh_size 0.7-2 um).
// The cause: on such a cloud the transformation of the essential boundary conditions
// is near singular (Lambda_CC, essential_bc.hpp), so a free particle's motion drives
// the constrained coordinates hundreds of times as far; the lumped transformation does
// not count their mass, and the discretisation's highest frequency is up to three
// times what the shortest edge over the wave speed predicts. stable_step = "auto" (the
// default) measures the step on such a cloud; a lattice keeps the wave-speed step.
#include "sim_fixtures.hpp"

#include "rkpm/rk/nodal_integration.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace rkpm::sim {
namespace {

std::string box_scene(const std::string& cloud) {
  return R"([scene]
name = "box"
[integrator]
t_end = 1e-5
[[body]]
name = "box"
[body.cloud]
)" + cloud + R"(
[body.material]
model = "mooney_rivlin"
c1 = 1000
lambda = 1e5
[[body.boundary]]
surface = "base"
type = "fixed"
[[term]]
type = "body_force"
body = "box"
acceleration = [0, 0, -1e3]
)";
}

std::string gmsh_box(double mesh_size) {
  const auto dir = testing::fresh_dir("constrained_tet_box");
  const auto geo = dir / "box.geo";
  testing::write_text(geo, "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 10, 10, 4};\n"
                           "Physical Surface(\"base\") = Surface In BoundingBox{-0.01, -0.01, -0.01, 10.01, 10.01, 0.01};\n");
  return "generator = \"gmsh\"\nfile = \"" + geo.string() + "\"\nmesh_size = " + std::to_string(mesh_size) +
         "\nscale = 1e-6";
}

// The largest physical displacement |u(X_J)| over the constrained particles, or over all.
double largest_motion(const Body& b, bool constrained_only) {
  double largest = 0.0;
  for (Index J = 0; J < static_cast<Index>(b.size()); ++J)
    if (!constrained_only || b.constraints.constrained(J, 2))
      largest = std::max(largest, rk::interpolate(b.interpolation, b.d, J).norm());
  return largest;
}

class ConstrainedTetBox : public ::testing::TestWithParam<double> {};

TEST_P(ConstrainedTetBox, MeasuresItsStepAndStaysStable) {
  testing::ScopedThreads one(1);
  auto sw = testing::build_from_text(box_scene(gmsh_box(GetParam())));
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  EXPECT_GT(integrator.constraint_amplification(), Integrator::kAmplifyingConstraints);
  ASSERT_TRUE(integrator.measures_stable_step()) << "stable_step = \"auto\" must measure on this cloud";
  const double dt0 = integrator.dt();
  for (int s = 0; s < 600; ++s) integrator.step();
  const Body& box = *sw.world->bodies[0];
  // With the wave-speed step, mesh_size 1 um grew an unstable mode: the motion limit cut
  // the step 58-fold in these 600 steps and |u| reached 2.5e-8 m. Stable, the step holds
  // and the box sags by at most twice the static sag of an incompressible column under
  // its weight, rho g H^2 / (2 E) with E = 3 mu = 6 c1: 1.3e-9 m.
  EXPECT_GT(integrator.dt(), 0.9 * dt0);
  const double static_sag = 1000.0 * 1e3 * 4e-6 * 4e-6 / (2.0 * 6.0 * 1000.0);
  EXPECT_LT(largest_motion(box, false), 2.0 * static_sag);
  EXPECT_LT(largest_motion(box, true), 1e-6 * static_sag) << "the fixed base moved";
}

INSTANTIATE_TEST_SUITE_P(MeshSizes, ConstrainedTetBox, ::testing::Values(0.7, 1.0, 1.5));

// The cause, measured: at mesh_size 1 um the true stable step is under half the
// wave-speed step, so the default safety factor 0.5 alone would step past it.
TEST(ConstrainedTetBox, AtMeshSizeOneTheWaveSpeedStepIsOverTwiceTheStableStep) {
  testing::ScopedThreads one(1);
  auto sw = testing::build_from_text(box_scene(gmsh_box(1.0)));
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  EXPECT_LT(integrator.stable_step_calibration(), 0.5);
}

// A lattice with the same fixed face keeps the wave-speed step: its transformation
// moves the constrained coordinates by about a tenth of the free ones' motion.
TEST(ConstrainedTetBox, ALatticeKeepsTheWaveSpeedStep) {
  testing::ScopedThreads one(1);
  std::string scene = box_scene("generator = \"block\"\nsize = [10e-6, 10e-6, 4e-6]\ncells = [10, 10, 4]");
  scene.replace(scene.find("surface = \"base\""), 16, "surface = \"zmin\"");
  auto sw = testing::build_from_text(scene);
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  EXPECT_LT(integrator.constraint_amplification(), 0.3);
  EXPECT_FALSE(integrator.measures_stable_step());
}

}  // namespace
}  // namespace rkpm::sim
