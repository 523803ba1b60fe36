#include "terms/contact/holding.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace rkpm::sim {

namespace {

// The point of triangle (a, b, c) farthest from its nearest corner, and that distance:
// the circumcentre of an acute (or right) triangle, the longest edge's midpoint of an
// obtuse one.
std::pair<Vec3, double> triangle_hollow(const Vec3& a, const Vec3& b, const Vec3& c) {
  const std::array<Vec3, 3> p = {a, b, c};
  // The angle opposite the longest edge decides.
  std::array<double, 3> edge2 = {(b - c).squaredNorm(), (c - a).squaredNorm(), (a - b).squaredNorm()};
  const int k = static_cast<int>(std::max_element(edge2.begin(), edge2.end()) - edge2.begin());
  const double others = edge2[(k + 1) % 3] + edge2[(k + 2) % 3];
  if (edge2[k] >= others) {  // obtuse or right at corner k
    const Vec3 mid = 0.5 * (p[(k + 1) % 3] + p[(k + 2) % 3]);
    return {mid, 0.5 * std::sqrt(edge2[k])};
  }
  const Vec3 ab = b - a, ac = c - a, n = ab.cross(ac);
  const Vec3 centre = a + (ac.squaredNorm() * n.cross(ab) + ab.squaredNorm() * ac.cross(n)) / (2.0 * n.squaredNorm());
  return {centre, (centre - a).norm()};
}

}  // namespace

SurfaceHollow widest_facing_hollow(const Body& body, const Vec3& towards) {
  const auto& cloud = body.cloud;
  SurfaceHollow widest;
  auto consider = [&](int i0, int i1, int i2) {
    const Vec3 &a = cloud.X[i0], &b = cloud.X[i1], &c = cloud.X[i2];
    const Vec3 normal = (b - a).cross(c - a);
    if (normal.dot(towards - (a + b + c) / 3.0) <= 0.0) return;
    const auto [centre, radius] = triangle_hollow(a, b, c);
    if (radius > widest.radius) widest = {radius, centre};
  };
  for (const auto& face : cloud.boundary_faces) {
    consider(face.nodes[0], face.nodes[1], face.nodes[2]);
    if (face.n_nodes == 4) consider(face.nodes[0], face.nodes[2], face.nodes[3]);
  }
  return widest;
}

}  // namespace rkpm::sim
