#include "cube_sphere.hpp"

#include <cmath>

namespace rkpm::particles::detail {

double equiangular(double s) {
  if (s == 1.0 || s == -1.0 || s == 0.0) return s;
  return std::tan(0.25 * M_PI * s);
}

Vec3 equiangular_direction(const Vec3& p) {
  int axis = 0;
  p.cwiseAbs().maxCoeff(&axis);
  const double t = std::abs(p[axis]);
  Vec3 d;
  for (int k = 0; k < 3; ++k) d[k] = k == axis ? (p[k] > 0 ? 1.0 : -1.0) : equiangular(p[k] / t);
  return d.normalized();
}

}  // namespace rkpm::particles::detail
