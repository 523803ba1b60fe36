// The initial director of the crawling scene's cell (examples/crawling/crawling.toml)
// must share the mirror symmetry of its uniform control (x -> -x, y -> -y about the
// cell's axis), like its clouds do (tests/particles/test_crawling_symmetry.cpp).
// The "surface_normal" rule gives an interior particle the normal of its nearest
// surface particle; a particle at the ball's centre has every surface particle
// equally near, so whichever normal it gets tilts the cell's anisotropic stiffness
// one way, and the uniform run then drifts (by 6.4 nm along x and y at the coarse
// resolution with 10 cells across).
#include "crawling_scene.hpp"
#include "mirror_checks.hpp"

#include "rkpm/sim/build.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>

namespace rkpm::sim {
namespace {

void expect_director_mirror_symmetric(bool coarse) {
  const scene::Scene s = rkpm::testing::crawling_scene(coarse);
  const Vec3 centre = s.find_body("cell")->cloud.vec3("center");
  const auto world = build_world(s);
  const Body& cell = *world->bodies[0];
  ASSERT_EQ(cell.name, "cell");
  ASSERT_TRUE((materials::lce::material_of(cell) != nullptr));
  const std::vector<Vec3>& h = materials::lce::material_of(cell)->director.h0;
  const double size = 2.0 * s.find_body("cell")->cloud.real("radius");
  for (int axis = 0; axis < 2; ++axis) {
    const auto partner = particles::testing::mirror_partner(cell.cloud, centre, axis, 1e-9 * size);
    double worst = 0.0;
    std::int32_t worst_particle = -1;
    for (std::int32_t i = 0; i < static_cast<std::int32_t>(cell.size()); ++i) {
      ASSERT_GE(partner[i], 0) << "particle " << i << " has no mirror image";
      Vec3 mirrored = h[i];
      mirrored[axis] = -mirrored[axis];
      // Nematic: h and -h are the same director.
      const double d = std::min((h[partner[i]] - mirrored).norm(), (h[partner[i]] + mirrored).norm());
      if (d > worst) {
        worst = d;
        worst_particle = i;
      }
    }
    std::cout << "  " << (coarse ? "coarse " : "") << "cell, " << (axis == 0 ? "x -> -x" : "y -> -y")
              << ": largest |h_j - M h_i| = " << worst << "\n";
    // Unit vectors from exactly mirrored normals: round-off is ~1e-16; a wrong
    // choice among a particle's equidistant surface neighbours is O(1).
    EXPECT_LT(worst, 1e-12) << "particle " << worst_particle << " at "
                            << (cell.cloud.X[std::max(worst_particle, 0)] - centre).transpose()
                            << " from the centre, director " << h[std::max(worst_particle, 0)].transpose();
  }
}

TEST(CrawlingDirector, InitialDirectorIsMirrorSymmetric) { expect_director_mirror_symmetric(false); }

TEST(CrawlingDirector, CoarseInitialDirectorIsMirrorSymmetric) { expect_director_mirror_symmetric(true); }

// With an even cell count a particle sits at the ball's centre, equally near every
// surface particle of the middle ring: the set-up warns and names it; with an odd
// count nothing is ambiguous and there is no warning.
TEST(CrawlingDirector, AmbiguousCentreDirectorIsWarnedAbout) {
  for (const std::int64_t cells : {10, 11}) {
    scene::Scene s = rkpm::testing::crawling_scene(true);
    for (scene::BodySpec& body : s.bodies)
      if (body.name() == "cell") body.cloud.set("cells", cells, 0, true);
    const auto world = build_world(s);
    if (cells % 2 == 0) {
      ASSERT_EQ(world->setup_warnings.size(), 1u);
      const std::string& w = world->setup_warnings.front();
      EXPECT_NE(w.find("body 'cell': [body.director] initial = \"surface_normal\": 1 particle(s) lie equally near"),
                std::string::npos) << w;
      // The centre particle, named by its position (the ball's centre).
      EXPECT_NE(w.find("(0, 0, 1.034e-05) m"), std::string::npos) << w;
    } else {
      EXPECT_TRUE(world->setup_warnings.empty()) << world->setup_warnings.front();
    }
  }
}

}  // namespace
}  // namespace rkpm::sim
