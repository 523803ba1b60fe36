// The Gmsh example scene (examples/spread_cell): a .geo cell and a .msh substrate build
// into a world whose physical surfaces carry the scene's boundary condition and terms,
// and the relaxation starts without a diagnosis.
#include "sim_fixtures.hpp"

#include <gtest/gtest.h>

namespace rkpm::sim {
namespace {

TEST(GmshExample, TheSpreadCellSceneBuildsFromItsGmshFilesAndSteps) {
  testing::ScopedThreads one(1);
  const scene::Scene scene = scene::load_scene(RKPM_SOURCE_DIR "/examples/spread_cell/spread_cell.toml");
  auto world = build_world(scene);
  ASSERT_EQ(world->bodies.size(), 2u);
  const Body& cell = *world->bodies[0];
  const Body& substrate = *world->bodies[1];
  EXPECT_EQ(cell.cloud.surface_names, (std::vector<std::string>{"surface", "bottom", "top"}));
  EXPECT_EQ(substrate.size(), 3125u);
  // The cell's underside is the plane z = 0; the substrate is held at its base.
  int bottom = 0;
  for (auto p : cell.cloud.boundary_particles)
    if (cell.cloud.on_surface(p, "bottom")) {
      EXPECT_NEAR(cell.cloud.X[p].z(), 0.0, 1e-12);
      ++bottom;
    }
  EXPECT_GT(bottom, 100);
  for (std::size_t i = 0; i < substrate.size(); ++i)
    for (int axis = 0; axis < 3; ++axis)
      EXPECT_EQ(substrate.constraints.constrained(static_cast<Index>(i), axis),
                substrate.cloud.on_surface(static_cast<std::int32_t>(i), "base"));
  Integrator integrator(*world, integrator_settings(scene));
  integrator.initialize();
  for (int s = 0; s < 20; ++s) integrator.step();
  EXPECT_GT(integrator.residual(), 0.0);
  EXPECT_TRUE(std::isfinite(integrator.residual()));
}

}  // namespace
}  // namespace rkpm::sim
