// The closed-form target of the convergence study: Lame's thick-walled sphere
// (inner radius a, outer radius b) under internal pressure p, small strain,
// isotropic linear elasticity (E, nu). With A, B the constants below,
//   u_r = A r + B / r^2,   eps_rr = A - 2 B / r^3,   eps_tt = A + B / r^3,
//   A = p a^3 (1 - 2 nu) / (E (b^3 - a^3)),   B = p a^3 (1 + nu) b^3 / (2 E (b^3 - a^3)),
// which is the u_r of the verification targets (section 7), centred at the origin.
#pragma once

#include "rkpm/common/types.hpp"

namespace rkpm::study {

// Isotropic Hooke's law sigma = lambda tr(eps) I + 2 mu eps.
struct IsotropicElasticity {
  double lambda = 0.0;
  double mu = 0.0;

  static IsotropicElasticity from_young_poisson(double E, double nu) {
    return {E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), E / (2.0 * (1.0 + nu))};
  }
  Mat3 stress(const Mat3& eps) const { return lambda * eps.trace() * Mat3::Identity() + 2.0 * mu * eps; }
  // eps : D : eps, twice the strain-energy density.
  double energy_product(const Mat3& eps) const { return eps.cwiseProduct(stress(eps)).sum(); }
};

struct LameSphere {
  double a = 1.0;      // inner radius
  double b = 2.0;      // outer radius
  double E = 1.0;
  double nu = 0.3;
  double p = 1e-3;     // internal pressure

  double coefficient_A() const { return p * a * a * a * (1.0 - 2.0 * nu) / (E * (b * b * b - a * a * a)); }
  double coefficient_B() const {
    return p * a * a * a * (1.0 + nu) * b * b * b / (2.0 * E * (b * b * b - a * a * a));
  }

  Vec3 displacement(const Vec3& X) const {
    const double r = X.norm();
    return (coefficient_A() + coefficient_B() / (r * r * r)) * X;  // u_r e_r = (u_r / r) X
  }

  Mat3 strain(const Vec3& X) const {
    const double r = X.norm();
    const double r3 = r * r * r;
    const double eps_rr = coefficient_A() - 2.0 * coefficient_B() / r3;
    const double eps_tt = coefficient_A() + coefficient_B() / r3;
    const Vec3 e = X / r;
    return eps_tt * Mat3::Identity() + (eps_rr - eps_tt) * e * e.transpose();
  }
};

}  // namespace rkpm::study
