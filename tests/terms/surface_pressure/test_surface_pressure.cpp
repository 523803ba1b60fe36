// The surface_pressure term on a block in its reference state: a pressure p on one
// flat face pushes it inwards with the total force p A, spread over the face's
// particles only; on the closed surface ("all") the forces cancel.
#include "sim_fixtures.hpp"

#include <gtest/gtest.h>

namespace rkpm::sim {
namespace {

std::string block_with_pressure(const std::string& surface) {
  return R"([scene]
name = "pressure"
[integrator]
mode = "relax"
[[body]]
name = "block"
density = 1000
[body.cloud]
generator = "block"
size = [2, 1, 0.5]
cells = [4, 3, 2]
[body.material]
model = "mooney_rivlin"
c1 = 400
lambda = 2000
[[term]]
type = "surface_pressure"
body = "block"
surface = ")" + surface + R"("
pressure = 300
)";
}

Vec3 total_pressure_force(testing::SceneWorld& w) {
  Body& b = *w.world->bodies[0];
  compute_internal_forces(b);  // F = I at rest: the current area is the reference area
  std::fill(b.force.begin(), b.force.end(), Vec3::Zero());
  w.world->terms[0]->add_forces(*w.world);
  Vec3 total = Vec3::Zero();
  for (const auto& f : b.force) total += f;
  return total;
}

TEST(SurfacePressure, FlatFaceCarriesPressureTimesArea) {
  auto w = testing::build_from_text(block_with_pressure("xmax"));
  const Vec3 total = total_pressure_force(w);
  const double area = 1.0 * 0.5;
  EXPECT_NEAR(total.x(), -300.0 * area, 1e-10 * 300.0 * area);  // inwards: -x on the xmax face
  EXPECT_NEAR(total.y(), 0.0, 1e-10 * 300.0 * area);
  EXPECT_NEAR(total.z(), 0.0, 1e-10 * 300.0 * area);
}

TEST(SurfacePressure, ClosedSurfaceCarriesNoNetForce) {
  auto w = testing::build_from_text(block_with_pressure("all"));
  EXPECT_LT(total_pressure_force(w).norm(), 1e-10 * 300.0);
}

}  // namespace
}  // namespace rkpm::sim
