// Closed-form (or quadrature) references for ellipsoids, used by tests and studies.
#include "rkpm/particles/generators.hpp"

#include "gauss_legendre.hpp"

#include <algorithm>
#include <cmath>

namespace rkpm::particles {
namespace {

bool nearly_equal(double a, double b) { return std::abs(a - b) <= 1e-14 * std::max(a, b); }

// Spheroid with equatorial semi-axis a and polar semi-axis c.
double spheroid_area(double a, double c) {
  if (nearly_equal(a, c)) return 4.0 * M_PI * a * a;
  if (c < a) {  // oblate
    const double e = std::sqrt(1.0 - (c * c) / (a * a));
    return 2.0 * M_PI * a * a * (1.0 + (1.0 - e * e) / e * std::atanh(e));
  }
  const double e = std::sqrt(1.0 - (a * a) / (c * c));  // prolate
  return 2.0 * M_PI * a * a * (1.0 + c / (a * e) * std::asin(e));
}

// Triaxial: |r_theta x r_phi| over (theta, phi); the periodic phi direction uses
// the trapezoidal rule, which converges exponentially for smooth periodic integrands.
double triaxial_area(double a, double b, double c) {
  const int n_phi = 512;
  return detail::integrate(
      [&](double theta) {
        const double s = std::sin(theta), co = std::cos(theta);
        double sum = 0.0;
        for (int k = 0; k < n_phi; ++k) {
          const double phi = 2.0 * M_PI * k / n_phi;
          const double cp = std::cos(phi), sp = std::sin(phi);
          sum += std::sqrt(b * b * c * c * s * s * cp * cp + a * a * c * c * s * s * sp * sp +
                           a * a * b * b * co * co);
        }
        return s * sum * (2.0 * M_PI / n_phi);
      },
      0.0, M_PI, M_PI / 64);
}

}  // namespace

double ellipsoid_volume(const Vec3& semi_axes) {
  return 4.0 / 3.0 * M_PI * semi_axes.x() * semi_axes.y() * semi_axes.z();
}

double ellipsoid_area(const Vec3& s) {
  if (!(s.minCoeff() > 0.0)) throw CloudError("ellipsoid_area: semi-axes must be positive");
  if (nearly_equal(s.x(), s.y())) return spheroid_area(s.x(), s.z());
  if (nearly_equal(s.x(), s.z())) return spheroid_area(s.x(), s.y());
  if (nearly_equal(s.y(), s.z())) return spheroid_area(s.y(), s.x());
  return triaxial_area(s.x(), s.y(), s.z());
}

Vec3 ellipsoid_normal(const Vec3& semi_axes, const Vec3& x) {
  return x.cwiseQuotient(semi_axes.cwiseProduct(semi_axes)).normalized();
}

}  // namespace rkpm::particles
