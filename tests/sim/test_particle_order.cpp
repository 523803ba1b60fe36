// [body.rk] particle_order = "morton" renumbers the cloud, not the physics: a relaxed
// block under gravity reaches the same displacement at every particle (matched by its
// reference position) as with the generator's numbering.
#include "sim_fixtures.hpp"

#include <gtest/gtest.h>

#include <iostream>
#include <map>

using namespace rkpm;
using namespace rkpm::sim;

namespace {

const std::string kSag = R"([scene]
name = "order"
[integrator]
mode = "relax"
relax_force_tol = 1e-9
[[body]]
name = "block"
density = 1000
[body.cloud]
generator = "block"
size = [1e-5, 6e-6, 4e-6]
cells = [7, 4, 3]
jitter = 0.2
[body.rk]
particle_order = "{order}"
[body.material]
model = "mooney_rivlin"
c1 = 400
c2 = 100
lambda = 4000
[[body.boundary]]
surface = "xmin"
type = "fixed"
[[term]]
type = "body_force"
body = "block"
acceleration = [0, 0, -2e3]
)";

// Displacement of each particle, keyed by its reference position.
std::map<std::array<double, 3>, Vec3> relaxed(const std::string& order) {
  sim::testing::ScopedThreads threads(1);
  auto sw = sim::testing::build_from_text(sim::testing::with(kSag, "order", order));
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  while (sw.world->step < 200000 && !integrator.converged()) integrator.step();
  EXPECT_TRUE(integrator.converged()) << order;
  const Body& body = *sw.world->bodies.front();
  std::vector<Vec3> u;
  physical_displacement(body, u);
  std::map<std::array<double, 3>, Vec3> by_position;
  for (std::size_t i = 0; i < body.size(); ++i)
    by_position[{body.cloud.X[i].x(), body.cloud.X[i].y(), body.cloud.X[i].z()}] = u[i];
  return by_position;
}

}  // namespace

TEST(ParticleOrder, MortonNumberingRelaxesToTheSameDisplacements) {
  const auto input = relaxed("input"), morton = relaxed("morton");
  ASSERT_EQ(input.size(), morton.size());
  double largest = 0.0, worst = 0.0;
  for (const auto& [X, u] : input) {
    const auto it = morton.find(X);
    ASSERT_NE(it, morton.end()) << "a particle moved in the reference configuration";
    largest = std::max(largest, u.norm());
    worst = std::max(worst, (it->second - u).norm());
  }
  std::cout << "largest displacement " << largest << " m, largest difference " << worst << " m\n";
  ASSERT_GT(largest, 1e-8);  // the block sags: something to compare
  // Both runs stop at the same tolerance, from paths that differ in round-off only.
  EXPECT_LE(worst, 1e-9 * largest) << "largest displacement " << largest;
}
