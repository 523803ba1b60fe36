// Modified Mooney-Rivlin hyperelastic solid: the extracellular matrix / substrate
// model of the seed paper (Fan & Li 2014, section 2.2, Eq. 9-11).
//
//   W(F) = c1 (I1 - 3 I3^(1/3)) + c2 (I2 - 3 I3^(2/3)) + (lambda/2) (ln I3)^2     (Eq. 9)
//
// with I1, I2, I3 the invariants of C = F^T F (Eq. 10); I3 = J^2, J = det F.
// Energy per unit reference volume [J/m^3 = Pa].
//
//   S = 2 [ (c1 + c2 I1) I - c2 C - (c1 J^(2/3) + 2 c2 J^(4/3) - 2 lambda ln J) C^-1 ]   (Eq. 11)
//   P = F S,   sigma = P F^T / J
//     = (2/J) [ (c1 + c2 I1) B - c2 B^2 - (c1 J^(2/3) + 2 c2 J^(4/3) - 2 lambda ln J) I ],  B = F F^T.
//
// The reference state is stress-free for any parameters. Small-strain moduli:
// shear mu = 2 (c1 + c2), bulk K = 4 lambda (so lambda is NOT Lame's first
// parameter; Lame's lambda is 4 lambda - 2 mu / 3).
//
// Value type: the force loop is templated on the material and calls these
// inline functions; a spatially graded body stores one MooneyRivlin per point
// (see graded_parameters.hpp).
#pragma once

#include "rkpm/common/types.hpp"
#include "materials/kinematics.hpp"

#include <algorithm>
#include <cmath>

namespace rkpm::materials {

struct MooneyRivlin {
  double c1 = 0.0;      // [Pa] coefficient of (I1 - 3 I3^(1/3)), seed Eq. 9
  double c2 = 0.0;      // [Pa] coefficient of (I2 - 3 I3^(2/3)), seed Eq. 9
  double lambda = 0.0;  // [Pa] coefficient of (1/2)(ln I3)^2, seed Eq. 9

  double shear_modulus() const { return 2.0 * (c1 + c2); }  // small-strain mu
  double bulk_modulus() const { return 4.0 * lambda; }      // small-strain K

  // Throws std::invalid_argument (naming the parameter and value) unless
  // mu = 2 (c1 + c2) > 0, lambda > 0 and all values are finite.
  void validate() const;

  // Strain energy per reference volume (Eq. 9) [Pa].
  double energy(const Mat3& F) const {
    const Mat3 C = F.transpose() * F;
    const double I1 = C.trace();
    const double I2 = 0.5 * (I1 * I1 - (C * C).trace());
    const double J = F.determinant();
    const double log_I3 = 2.0 * std::log(J);
    return c1 * (I1 - 3.0 * std::cbrt(J * J)) + c2 * (I2 - 3.0 * std::cbrt(J * J * J * J)) +
           0.5 * lambda * log_I3 * log_I3;
  }

  // First Piola-Kirchhoff stress P = dW/dF = F S (Eq. 11) [Pa].
  Mat3 first_piola(const Mat3& F) const {
    const Kinematics k(F);
    const Mat3 C = F.transpose() * F;
    return 2.0 * ((c1 + c2 * C.trace()) * F - c2 * (F * C) - pressure_term(k.J, k.log_J) * k.F_inv_T);
  }

  // Cauchy stress sigma = P F^T / J, written in B = F F^T (symmetric) [Pa].
  Mat3 cauchy(const Mat3& F) const {
    const double J = F.determinant();
    const Mat3 B = F * F.transpose();
    return (2.0 / J) * ((c1 + c2 * B.trace()) * B - c2 * (B * B) -
                        pressure_term(J, std::log(J)) * Mat3::Identity());
  }

  // Conservative longitudinal wave speed [m/s] for the stable time step, in the
  // reference configuration (total Lagrangian: divide the reference particle
  // spacing by it), rho0 = reference density [kg/m^3].
  //
  // The acoustic tensor Q(N)_ik = dP_iJ/dF_kL N_J N_L of this energy is, with
  // a = F N, b = F^-T N (derivation in docs/theory/materials.md):
  //   Q = 2 (c1 + c2 (I1 - |a|^2)) I + 2 c2 (a a^T - B) + 2 (p - J p') b b^T,
  //   p(J) = c1 J^(2/3) + 2 c2 J^(4/3) - 2 lambda ln J.
  // a a^T - B is negative semidefinite, |a|^2 = N.C N and |b|^2 = N.C^-1 N, so
  //   max_N lambda_max(Q) <= 2 c1 + 2 c2 I1 + max_i (-2 c2 C_i + 2 q / C_i)
  //                          + (c2 < 0 ? 2 |c2| C_max : 0),   q = max(0, p - J p'),
  // C_i the eigenvalues of C (C and C^-1 commute). At F = I the bound is exact:
  // rho0 c^2 = K + 4 mu / 3, the P-wave modulus.
  double wave_speed(const Mat3& F, double rho0) const {
    const Mat3 C = F.transpose() * F;
    const Vec3 eig = symmetric_eigenvalues(C);
    const double J = F.determinant();
    const double J23 = std::cbrt(J * J);
    const double q = std::max(0.0, c1 * J23 / 3.0 - 2.0 * c2 * J23 * J23 / 3.0 +
                                       2.0 * lambda * (1.0 - std::log(J)));
    double directional = -2.0 * c2 * eig[0] + 2.0 * q / eig[0];
    for (int i = 1; i < 3; ++i) directional = std::max(directional, -2.0 * c2 * eig[i] + 2.0 * q / eig[i]);
    double bound = 2.0 * c1 + 2.0 * c2 * C.trace() + directional;
    if (c2 < 0.0) bound += 2.0 * (-c2) * eig[2];
    return std::sqrt(std::max(bound, 0.0) / rho0);
  }

 private:
  // p(J) = c1 J^(2/3) + 2 c2 J^(4/3) - 2 lambda ln J: the coefficient of C^-1 in
  // S / 2 (Eq. 11 with I3^(1/3) = J^(2/3), ln I3 = 2 ln J).
  double pressure_term(double J, double log_J) const {
    const double J23 = std::cbrt(J * J);
    return c1 * J23 + 2.0 * c2 * J23 * J23 - 2.0 * lambda * log_J;
  }
};

}  // namespace rkpm::materials
