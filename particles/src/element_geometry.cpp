#include "rkpm/particles/element_geometry.hpp"

#include "element_topology.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace rkpm::particles {
namespace {

// Trilinear hexahedron: det J is at most quadratic in each reference coordinate,
// so 2x2x2 Gauss integrates the volume exactly.
double hex_volume(const Cloud& cloud, const std::int32_t* n) {
  static const double sign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                    {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  const double g = 1.0 / std::sqrt(3.0);
  double volume = 0.0;
  for (int q = 0; q < 8; ++q) {
    const double xi[3] = {g * sign[q][0], g * sign[q][1], g * sign[q][2]};
    Eigen::Matrix3d jac = Eigen::Matrix3d::Zero();
    for (int a = 0; a < 8; ++a) {
      const double f[3] = {1 + sign[a][0] * xi[0], 1 + sign[a][1] * xi[1], 1 + sign[a][2] * xi[2]};
      const Vec3 dN(sign[a][0] * f[1] * f[2] / 8, sign[a][1] * f[0] * f[2] / 8, sign[a][2] * f[0] * f[1] / 8);
      jac += cloud.X[n[a]] * dN.transpose();
    }
    volume += jac.determinant();  // Gauss weights are all 1 on [-1, 1]^3
  }
  return volume;
}

}  // namespace

double element_volume(const Cloud& cloud, int e) {
  const std::int32_t* n = cloud.mesh.element_nodes(e);
  if (cloud.mesh.type[e] == ElementType::Hex8) return hex_volume(cloud, n);
  const Vec3& x0 = cloud.X[n[0]];
  return (cloud.X[n[1]] - x0).cross(cloud.X[n[2]] - x0).dot(cloud.X[n[3]] - x0) / 6.0;
}

double element_min_scaled_jacobian(const Cloud& cloud, int e) {
  const auto& topo = detail::topology(cloud.mesh.type[e]);
  const std::int32_t* n = cloud.mesh.element_nodes(e);
  double quality = 1.0;
  for (int k = 0; k < topo.n_nodes; ++k) {
    const auto& nb = topo.corner_neighbors[k];
    const Vec3& x = cloud.X[n[k]];
    const Vec3 e1 = cloud.X[n[nb[0]]] - x, e2 = cloud.X[n[nb[1]]] - x, e3 = cloud.X[n[nb[2]]] - x;
    const double lengths = e1.norm() * e2.norm() * e3.norm();
    const double det = e1.cross(e2).dot(e3);
    quality = std::min(quality, lengths > 0.0 ? det / lengths : 0.0);
  }
  return quality;
}

}  // namespace rkpm::particles
