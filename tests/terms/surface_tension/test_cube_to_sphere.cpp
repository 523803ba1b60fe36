// Surface tension alone turns a soft cube into a sphere (VERIFICATION section 5): at
// constant volume L^3 the least-area shape is the ball of radius (3/(4 pi))^(1/3) L
// = 0.62035 L, with area 0.806 of the cube's.
//
// The body is a coarse Mooney-Rivlin cube whose shear modulus is small against the
// tension (mu L / gamma = 0.1: its elastic energy at the sphere is a few per cent of
// the surface energy released) and whose bulk modulus is large (lambda L / gamma =
// 300: the Laplace pressure 3.2 gamma / L changes the volume by about 1 %). Damped
// dynamics relax it; the shape is measured on the boundary particles (where the
// tension acts), as their mean distance from the body's centre of mass and its
// spread.
//
// How resolution enters: the cloud has n = 6 cells per edge. A faceted surface of n
// cells per edge has corners and edges that a single face's tension cannot round
// below the spacing L/n, and the mean distance of the boundary particles of a
// polyhedron inscribed in the sphere is below its circumscribed radius by O(1/n^2);
// both errors shrink with n. Measured (mean radius, spread of the distances, max -
// min over mean): n = 6: +0.14 %, 0.080; n = 8: -0.11 %, 0.059; the cube starts at
// +4.5 %, 0.56. The spread that remains is the elastic resistance (mu L / gamma)
// plus the faceting: a softer cube (mu L / gamma = 0.05) rounds further but its
// surface layer then creeps under the tension within 10^4 steps.
#include "contact_fixtures.hpp"

#include "rkpm/sim/build.hpp"
#include "rkpm/sim/integrator.hpp"
#include "terms/surface_tension/surface_tension.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace rkpm::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string cube_scene(int cells, double c1, double lambda, double damping) {
  return R"([scene]
name = "cube"
[integrator]
mode = "dynamic"
t_end = 1e9
dt = 0
damping = )" + std::to_string(damping) + R"(
[[body]]
name = "cube"
density = 1000
[body.cloud]
generator = "block"
origin = [-0.5, -0.5, -0.5]
size = [1.0, 1.0, 1.0]
cells = [)" + std::to_string(cells) + ", " + std::to_string(cells) + ", " + std::to_string(cells) + R"(]
[body.material]
model = "mooney_rivlin"
c1 = )" + std::to_string(c1) + R"(
c2 = 0
lambda = )" + std::to_string(lambda) + R"(
[[term]]
type = "surface_tension"
body = "cube"
gamma = 1.0
)";
}

struct Shape {
  double mean_radius = 0.0, spread = 0.0;
  double volume = 0.0;          // sum_L J_L V_L
  double faceted_volume = 0.0;  // enclosed by the faceted surface (below volume by O(h^2) on a sphere)
};

// Boundary particles' distances from the centre of mass, and the enclosed volume,
// at the physical positions X + u(X) (the surface the tension acts on).
Shape measure(const Body& body) {
  std::vector<Vec3> p;
  physical_displacement(body, p);
  Vec3 centre = Vec3::Zero();
  double mass = 0.0;
  for (std::size_t i = 0; i < body.size(); ++i) {
    p[i] += body.cloud.X[i];
    centre += body.mass[i] * nodal_position(body, static_cast<Index>(i));
    mass += body.mass[i];
  }
  centre /= mass;
  Shape s;
  double lo = INFINITY, hi = 0.0;
  for (Index i : body.cloud.boundary_particles) {
    const double r = (p[i] - centre).norm();
    s.mean_radius += r;
    lo = std::min(lo, r);
    hi = std::max(hi, r);
  }
  s.mean_radius /= static_cast<double>(body.cloud.boundary_particles.size());
  s.spread = (hi - lo) / s.mean_radius;
  for (const auto& face : body.cloud.boundary_faces) {
    // Divergence theorem on the faceted surface: V = sum over triangles of (a . (b x c)) / 6.
    const auto* n = face.nodes;
    const Vec3 &a = p[n[0]], &b = p[n[1]], &c = p[n[2]];
    s.faceted_volume += a.dot(b.cross(c)) / 6.0;
    if (face.n_nodes == 4) s.faceted_volume += a.dot(c.cross(p[n[3]])) / 6.0;
  }
  for (std::size_t L = 0; L < body.size(); ++L) s.volume += body.F[L].determinant() * body.cloud.volume[L];
  return s;
}

TEST(SurfaceTension, CubeRelaxesTowardTheSphereOfEqualVolume) {
  // 6 cells per edge (343 particles); mu L / gamma = 0.1, lambda L / gamma = 300;
  // damping 0.2 / s against an oscillation period of about 2 pi sqrt(rho L^3 / (12 gamma)) = 57 s.
  auto w = testing::world_from_text(cube_scene(6, 0.05, 300.0, 0.2));
  Integrator integrator(*w.world, integrator_settings(w.scene));
  integrator.initialize();
  const Body& cube = *w.world->bodies.front();
  const Shape start = measure(cube);
  Shape before_last;
  for (int k = 1; k <= 6000; ++k) {
    integrator.step();
    if (k == 4000) before_last = measure(cube);
  }
  const Shape end = measure(cube);
  const double sphere = std::cbrt(3.0 / (4.0 * kPi));
  std::printf("cube: mean r %.5f, spread %.4f; after %lld steps (t = %.0f s): mean r %.5f (sphere %.5f: %+.2f %%), "
              "spread %.4f, volume %.5f (faceted %.5f); 2000 steps before: mean r %.5f\n",
              start.mean_radius, start.spread, static_cast<long long>(w.world->step), w.world->time, end.mean_radius,
              sphere, 100.0 * (end.mean_radius / sphere - 1.0), end.spread, end.volume, end.faceted_volume,
              before_last.mean_radius);
  EXPECT_GT(start.spread, 0.5);  // the measure tells a cube from a sphere
  EXPECT_NEAR(end.mean_radius, sphere, 0.02 * sphere);
  EXPECT_LT(end.spread, 0.1);
  EXPECT_NEAR(end.volume, 1.0, 0.02);  // constant volume
  EXPECT_NEAR(end.mean_radius, before_last.mean_radius, 1e-3 * sphere);  // relaxed, not passing through
}

}  // namespace
}  // namespace rkpm::sim
