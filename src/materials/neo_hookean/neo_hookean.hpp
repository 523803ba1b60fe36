// Compressible neo-Hookean solid: the common baseline of soft-tissue and gel models
// (not part of the seed paper; its Mooney-Rivlin Eq. 9 with c2 = 0 differs in the
// volumetric part). With the Lame constants mu and lambda,
//
//   W(F) = mu/2 (I1 - 3) - mu ln J + (lambda/2) (ln J)^2,     I1 = tr C = |F|^2, J = det F,
//   P = dW/dF = mu (F - F^-T) + lambda ln J F^-T,
//   sigma = P F^T / J = [ mu (B - I) + lambda ln J I ] / J,   B = F F^T.
//
// Energy per unit reference volume [J/m^3 = Pa]. The reference state is stress-free
// and W = 0 there (F = I: F - F^-T = 0, ln J = 0). Small strain: shear modulus mu,
// bulk modulus lambda + 2 mu / 3, P-wave modulus lambda + 2 mu.
//
// Value type with inline stress functions, like the other kernels: the force loop calls
// them per point without a virtual call.
#pragma once

#include "materials/kinematics.hpp"
#include "rkpm/common/types.hpp"

#include <algorithm>
#include <cmath>

namespace rkpm::materials {

struct NeoHookean {
  double mu = 0.0;      // [Pa] shear modulus, Lame's second parameter
  double lambda = 0.0;  // [Pa] Lame's first parameter

  double shear_modulus() const { return mu; }                      // small-strain mu
  double bulk_modulus() const { return lambda + 2.0 * mu / 3.0; }  // small-strain K

  // Throws std::invalid_argument (naming the parameter and value) unless mu > 0,
  // lambda > 0 and both are finite.
  void validate() const;

  // Strain energy per reference volume [Pa].
  double energy(const Mat3& F) const {
    const double log_J = std::log(F.determinant());
    return 0.5 * mu * (F.squaredNorm() - 3.0) - mu * log_J + 0.5 * lambda * log_J * log_J;
  }

  // First Piola-Kirchhoff stress P = dW/dF [Pa].
  Mat3 first_piola(const Mat3& F) const {
    const Kinematics k(F);
    return mu * F + (lambda * k.log_J - mu) * k.F_inv_T;
  }

  // Cauchy stress sigma = P F^T / J, written in B = F F^T (symmetric) [Pa].
  Mat3 cauchy(const Mat3& F) const {
    const double J = F.determinant();
    return (1.0 / J) * (mu * (F * F.transpose() - Mat3::Identity()) + (lambda * std::log(J)) * Mat3::Identity());
  }

  // Longitudinal wave speed [m/s] for the stable time step, in the reference
  // configuration (divide the reference particle spacing by it), rho0 = reference
  // density [kg/m^3]. The acoustic tensor of this energy is, with b = F^-T N
  // (derivation in docs/theory/materials.md),
  //   Q(N) = mu I + (mu + lambda - lambda ln J) b b^T,
  // so its largest eigenvalue over unit m and N is
  //   rho0 c^2 = mu + max(0, mu + lambda - lambda ln J) / C_min,
  // C_min the smallest eigenvalue of C (|b|^2 = N.C^-1 N <= 1 / C_min). That is the
  // exact maximum for every F, hence a valid bound at finite strain; at F = I it is the
  // P-wave modulus lambda + 2 mu.
  double wave_speed(const Mat3& F, double rho0) const {
    const double smallest_stretch_squared = symmetric_eigenvalues(F.transpose() * F)[0];
    const double volumetric = std::max(0.0, mu + lambda - lambda * std::log(F.determinant()));
    return std::sqrt((mu + volumetric / smallest_stretch_squared) / rho0);
  }
};

}  // namespace rkpm::materials
