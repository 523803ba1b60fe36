// The director's distance from its own equilibrium (sim::director_residual): at rest and
// F = I the part of dF/dh across h is mu (s-1)^2/s (h . h0) (h0 - (h . h0) h) (Eq. 6 at
// F = I, no Frank term), so a director turned by theta from h0 gives
// |dh/dt| / (L mu) = (s-1)^2/s sin(theta) cos(theta); on h0 it is zero.
#include "sim_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>

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
cells = [3, 3, 3]
[body.material]
model = "lce"
mu = 1e4
bulk = 1e5
s = 2.0
mobility = 1e3
[body.director]
initial = "fixed"
vector = [0, 0, 1]
boundary = "free"
)";

double residual_with_director_turned_by(double theta) {
  testing::ScopedThreads one(1);
  auto sw = testing::build_from_text(kBlockAtRest);
  Body& body = *sw.world->bodies.front();
  for (Vec3& h : body.director->h) h = Vec3(std::sin(theta), 0.0, std::cos(theta));
  (void)advance_director(body, 1e-15);  // computes dh/dt at the turned director, at rest
  return director_residual(body);
}

TEST(DirectorResidual, ATurnedDirectorAtRestGivesTheClosedFormMolecularField) {
  const double s = 2.0;
  for (const double theta : {0.1, 0.3, 0.7}) {
    const double expected = (s - 1.0) * (s - 1.0) / s * std::sin(theta) * std::cos(theta);
    EXPECT_NEAR(residual_with_director_turned_by(theta), expected, 1e-9 * expected) << "theta = " << theta;
  }
  EXPECT_LT(residual_with_director_turned_by(0.0), 1e-14);
}

}  // namespace
}  // namespace rkpm::sim
