// Surface tension (seed Eq. 15-17, isotropic surface stress): the force is the exact
// gradient of gamma * area, the area is that of the faceted surface, and a relaxed
// elastic sphere carries the Young-Laplace pressure 2 gamma / R (VERIFICATION section 5).
#include "contact_fixtures.hpp"

#include "rkpm/particles/generators.hpp"
#include "rkpm/sim/build.hpp"
#include "rkpm/sim/integrator.hpp"
#include "terms/surface_tension/surface_tension.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace rkpm::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A jittered block with a random displacement field: warped quadrilateral faces.
std::unique_ptr<Body> warped_block(std::uint64_t seed) {
  particles::BlockSpec s;
  s.size = Vec3(1.0, 0.8, 0.6);
  s.cells = {4, 3, 3};
  s.jitter = 0.2;
  auto cloud = particles::make_block(s);
  auto body = testing::particle_body("block", cloud.X, cloud.volume);
  body->cloud = std::move(cloud);
  testing::Random rng{seed};
  std::vector<Vec3> d(body->size());
  for (auto& v : d) v = 0.05 * rng.vector();
  testing::move_to(*body, d);
  return body;
}

TEST(SurfaceTension, ForceIsMinusGammaTimesTheAreaGradient) {
  auto body = warped_block(3);
  const double gamma = 0.7;
  SurfaceTension tension(*body, "all", gamma);
  World w;
  std::fill(body->force.begin(), body->force.end(), Vec3::Zero());
  tension.add_forces(w);
  const std::vector<Vec3> f = body->force;
  double worst = 0.0, scale = 0.0;
  for (Index i : body->cloud.boundary_particles)
    for (int k = 0; k < 3; ++k) {
      const double h = 1e-6, d0 = body->d[i][k];
      body->d[i][k] = d0 + h;
      const double e_plus = gamma * tension.measure_area();
      body->d[i][k] = d0 - h;
      const double e_minus = gamma * tension.measure_area();
      body->d[i][k] = d0;
      worst = std::max(worst, std::abs(-(e_plus - e_minus) / (2.0 * h) - f[i][k]));
      scale = std::max(scale, std::abs(f[i][k]));
    }
  // Translations and rotations leave the area unchanged: no net force or torque.
  Vec3 total = Vec3::Zero(), torque = Vec3::Zero();
  for (std::size_t i = 0; i < body->size(); ++i) {
    total += f[i];
    torque += nodal_position(*body, static_cast<Index>(i)).cross(f[i]);
  }
  std::printf("area %.6f; largest |f + dE/dx| %.2e of %.2e; |sum f| %.1e, |sum x x f| %.1e\n", tension.area(), worst,
              scale, total.norm(), torque.norm());
  EXPECT_LE(worst, 1e-7 * scale);
  EXPECT_LE(total.norm(), 1e-12 * scale);
  EXPECT_LE(torque.norm(), 1e-12 * scale);
  EXPECT_DOUBLE_EQ(tension.stored_energy(w), gamma * tension.area());
}

TEST(SurfaceTension, AreaOfPlanarAndNamedSurfacesIsExact) {
  particles::BlockSpec s;
  s.size = Vec3(1.0, 0.8, 0.6);
  s.cells = {4, 3, 3};
  s.jitter = 0.2;  // moves particles within the faces: the faces stay planar
  auto cloud = particles::make_block(s);
  auto body = testing::particle_body("block", cloud.X, cloud.volume);
  body->cloud = std::move(cloud);
  EXPECT_NEAR(SurfaceTension(*body, "all", 1.0).area(), 2 * (0.8 + 0.48 + 0.6), 1e-12);
  EXPECT_NEAR(SurfaceTension(*body, "zmax", 1.0).area(), 0.8, 1e-12);
  EXPECT_THROW(SurfaceTension(*body, "top", 1.0), std::invalid_argument);
}

// A Mooney-Rivlin sphere (mu = 1000 Pa, K = 8000 Pa) under surface tension only,
// relaxed with FIRE. Young-Laplace: uniform pressure 2 gamma / R inside, so the mean
// stress -tr(sigma)/3 is 2 gamma / R and the radius shrinks by 2 gamma / (3 K R) R.
const std::string kSphere = R"([scene]
name = "droplet"
[integrator]
mode = "relax"
t_end = 1e6
relax_force_tol = 1e-7
relax_velocity_tol = 1e-12
max_steps = 100000
[[body]]
name = "ball"
density = 1000
[body.cloud]
generator = "sphere"
radius = 1.0
cells = 8
[body.material]
model = "mooney_rivlin"
c1 = 400
c2 = 100
lambda = 2000
[[term]]
type = "surface_tension"
body = "ball"
gamma = 4.0
)";

TEST(SurfaceTension, RelaxedSphereCarriesTheYoungLaplacePressure) {
  auto w = testing::world_from_text(kSphere);
  Integrator integrator(*w.world, integrator_settings(w.scene));
  integrator.initialize();
  while (!integrator.converged() && w.world->step < 100000) integrator.step();
  ASSERT_TRUE(integrator.converged()) << "residual " << integrator.residual();
  const Body& ball = *w.world->bodies.front();
  const double gamma = 4.0, R = 1.0, K = 8000.0, expected = 2.0 * gamma / R;
  double interior = 0.0, interior_volume = 0.0, all = 0.0, all_volume = 0.0;
  for (std::size_t L = 0; L < ball.size(); ++L) {
    const double J = ball.F[L].determinant();
    const Mat3 sigma = first_piola_at(ball, static_cast<Index>(L)) * ball.F[L].transpose() / J;
    const double v = J * ball.cloud.volume[L], pressure = -sigma.trace() / 3.0;
    all += v * pressure;
    all_volume += v;
    if (ball.cloud.X[L].norm() < 0.5 * R) {
      interior += v * pressure;
      interior_volume += v;
    }
  }
  interior /= interior_volume;
  all /= all_volume;
  // Radius change from the volume: V = V0 (1 + 3 u_r/R) at small strain.
  double v0 = 0.0;
  for (double v : ball.cloud.volume) v0 += v;
  const double radial_strain = (all_volume / v0 - 1.0) / 3.0;
  const double expected_strain = -2.0 * gamma / (3.0 * K * R);
  std::printf("FIRE %lld steps; pressure: interior %.4f Pa, body mean %.4f Pa, 2 gamma / R = %.4f Pa "
              "(errors %.2f %%, %.2f %%); u_r / r = %.4e (closed form %.4e)\n",
              static_cast<long long>(w.world->step), interior, all, expected, 100.0 * (interior / expected - 1.0),
              100.0 * (all / expected - 1.0), radial_strain, expected_strain);
  EXPECT_NEAR(interior, expected, 0.02 * expected);
  EXPECT_NEAR(all, expected, 0.02 * expected);
  EXPECT_NEAR(radial_strain, expected_strain, 0.03 * std::abs(expected_strain));
}

}  // namespace
}  // namespace rkpm::sim
