// The body_force term: f_I = m_I g on every particle, and its power sum_I m_I g . v_I.
#include "sim_fixtures.hpp"

#include "terms/body_force/body_force.hpp"

#include <gtest/gtest.h>

namespace rkpm::sim {
namespace {

const std::string kBlock = R"([scene]
name = "gravity"
[integrator]
mode = "relax"
[[body]]
name = "block"
density = 1200
[body.cloud]
generator = "block"
size = [1, 0.5, 0.5]
cells = [4, 2, 2]
jitter = 0.2
[body.material]
model = "mooney_rivlin"
c1 = 400
lambda = 2000
[[term]]
type = "body_force"
body = "block"
acceleration = [0.5, -1, -9.81]
)";

TEST(BodyForce, AddsMassTimesAccelerationAndReportsItsPower) {
  auto w = testing::build_from_text(kBlock);
  Body& b = *w.world->bodies[0];
  ASSERT_EQ(w.world->terms.size(), 1u);
  Term& term = *w.world->terms[0];
  EXPECT_EQ(term.name(), "body_force");
  const Vec3 g(0.5, -1, -9.81);
  std::fill(b.force.begin(), b.force.end(), Vec3(1, 2, 3));
  term.add_forces(*w.world);
  double mass = 0.0, power = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    EXPECT_EQ(b.force[i], Vec3(1, 2, 3) + b.mass[i] * g) << i;  // added, not assigned
    b.v[i] = Vec3(0.1 * static_cast<double>(i), 1.0, -2.0);
    power += b.mass[i] * g.dot(b.v[i]);
    mass += b.mass[i];
  }
  EXPECT_NEAR(mass, 1200 * 0.25, 1e-12 * mass);  // lumped masses carry the body's mass
  EXPECT_NEAR(term.power(*w.world), power, 1e-12 * std::abs(power));
  EXPECT_EQ(term.stored_energy(*w.world), 0.0);  // it does work, it stores nothing
}

}  // namespace
}  // namespace rkpm::sim
