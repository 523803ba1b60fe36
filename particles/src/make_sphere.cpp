#include "rkpm/particles/generators.hpp"

#include "cube_sphere.hpp"
#include "structured_grid.hpp"

#include <algorithm>
#include <cmath>

namespace rkpm::particles {
namespace {

// Cube [-1, 1]^3 -> unit ball. With t the max-norm of p and d(p) its equiangular
// direction, x = (1 - w) p + w t d(p): w(0) = 0 keeps the centre a cube grid and
// w(1) = 1 puts the cube's surface t = 1 exactly onto the sphere. The radius
// along the cube's diagonal is r(t) = t (sqrt(3) - (sqrt(3) - 1) w), which must
// grow with t or the corner cells invert: w = t^2 fails (r'(1) < 0). With
// w = t (2 - t), w'(1) = 0 gives r'(1) = 1, the same radial spacing at the
// surface in every direction, and r' >= 0.75 everywhere.
Vec3 cube_to_ball(const Vec3& p) {
  const double t = p.cwiseAbs().maxCoeff();
  if (t == 0.0) return Vec3::Zero();
  const double w = t * (2.0 - t);
  return (1.0 - w) * p + w * t * detail::equiangular_direction(p);
}

}  // namespace

Cloud make_sphere(const SphereSpec& spec) {
  if (spec.cells < 2) {
    throw CloudError("make_sphere: cells = " + std::to_string(spec.cells) + ", expected >= 2");
  }
  if (!(spec.radius > 0.0)) {
    throw CloudError("make_sphere: radius = " + std::to_string(spec.radius) + ", expected > 0");
  }
  const int n = spec.cells;
  const detail::StructuredGrid grid{{n, n, n}};
  grid.check("make_sphere");
  Cloud cloud;
  cloud.name = "sphere";
  cloud.surface_names = {"surface"};
  cloud.X.resize(grid.n_nodes());
  cloud.surface_mask.assign(grid.n_nodes(), 0);
  for (int k = 0; k <= n; ++k) {
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        // Integer arithmetic first: mirrored nodes get exactly mirrored coordinates.
        const Vec3 p(double(2 * i - n) / n, double(2 * j - n) / n, double(2 * k - n) / n);
        const std::int32_t id = grid.node(i, j, k);
        cloud.X[id] = spec.center + spec.radius * cube_to_ball(p);
        if (grid.on_boundary(i, j, k)) cloud.surface_mask[id] = 1;
      }
    }
  }
  grid.add_hexahedra(cloud.mesh);
  finalize_cloud(cloud);
  return cloud;
}

}  // namespace rkpm::particles
