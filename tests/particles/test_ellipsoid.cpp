#include "cloud_checks.hpp"

#include "rkpm/particles/generators.hpp"

#include <Eigen/Geometry>

namespace rkpm::particles {
namespace {

// Independent reference: area of a fine (theta, phi) triangulation, corrected for
// its O(h^2) error by Richardson extrapolation of two resolutions.
double triangulated_area(const Vec3& s, int n) {
  auto point = [&](int i, int j) {
    const double t = M_PI * i / n, p = 2.0 * M_PI * j / (2 * n);
    return Vec3(s.x() * std::sin(t) * std::cos(p), s.y() * std::sin(t) * std::sin(p), s.z() * std::cos(t));
  };
  double area = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < 2 * n; ++j) {
      const Vec3 a = point(i, j), b = point(i + 1, j), c = point(i + 1, j + 1), d = point(i, j + 1);
      area += 0.5 * (b - a).cross(c - a).norm() + 0.5 * (c - a).cross(d - a).norm();
    }
  }
  return area;
}

double extrapolated_area(const Vec3& s) { return (4.0 * triangulated_area(s, 400) - triangulated_area(s, 200)) / 3.0; }

TEST(Ellipsoid, VolumeAndSphereArea) {
  EXPECT_NEAR(ellipsoid_volume(Vec3(1, 2, 3)), 8.0 * M_PI, 1e-14);
  EXPECT_NEAR(ellipsoid_area(Vec3(2, 2, 2)), 16.0 * M_PI, 1e-13);
}

TEST(Ellipsoid, AreaMatchesTriangulation) {
  for (const Vec3& s : {Vec3(5, 5, 1.5), Vec3(1, 1, 3), Vec3(1, 3, 1), Vec3(1, 2, 3), Vec3(4.5, 4.5, 1.0)}) {
    const double error = testing::relative_error(ellipsoid_area(s), extrapolated_area(s));
    testing::report("ellipsoid area vs triangulation, axes " + std::to_string(s.x()) + "," + std::to_string(s.y()) +
                        "," + std::to_string(s.z()),
                    error);
    EXPECT_LT(error, 1e-6);
  }
}

TEST(Ellipsoid, NearSpheroidIsContinuous) {
  // The triaxial quadrature and the spheroid closed form must agree in the limit.
  const double spheroid = ellipsoid_area(Vec3(5, 5, 1.5));
  const double triaxial = ellipsoid_area(Vec3(5, 5 * (1 + 1e-9), 1.5));
  EXPECT_LT(testing::relative_error(triaxial, spheroid), 1e-8);
}

TEST(Ellipsoid, NormalIsTheGradientDirection) {
  const Vec3 s(5, 5, 1.5);
  EXPECT_LT((ellipsoid_normal(s, Vec3(0, 0, 1.5)) - Vec3(0, 0, 1)).norm(), 1e-15);
  EXPECT_LT((ellipsoid_normal(s, Vec3(-5, 0, 0)) - Vec3(-1, 0, 0)).norm(), 1e-15);
  // At any surface point the normal is orthogonal to the tangent of a curve on the surface.
  const double t = 0.7, p = 1.1, h = 1e-6;
  auto x = [&](double tt) { return Vec3(5 * std::sin(tt) * std::cos(p), 5 * std::sin(tt) * std::sin(p), 1.5 * std::cos(tt)); };
  const Vec3 tangent = (x(t + h) - x(t - h)) / (2 * h);
  EXPECT_LT(std::abs(ellipsoid_normal(s, x(t)).dot(tangent.normalized())), 1e-9);
}

TEST(Ellipsoid, RejectsNonPositiveAxes) { EXPECT_THROW(ellipsoid_area(Vec3(1, 0, 1)), CloudError); }

}  // namespace
}  // namespace rkpm::particles
