// Small tensor helpers shared by the constitutive models: the quantities every
// material needs from the deformation gradient F, computed once per call.
#pragma once

#include "rkpm/common/types.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>

namespace rkpm::materials {

// Volumetric kinematics of F. Requires det F > 0; for det F <= 0 (an inverted
// point) log_J is NaN and every stress computed from it is NaN, which the
// simulator's blow-up check reports. Materials do not throw in the force loop:
// an exception cannot leave an OpenMP parallel region.
struct Kinematics {
  Mat3 F_inv;     // F^-1
  Mat3 F_inv_T;   // F^-T, the cofactor direction: d(det F)/dF = J F^-T
  double J;       // det F
  double log_J;   // ln J

  explicit Kinematics(const Mat3& F)
      : F_inv(F.inverse()), F_inv_T(F_inv.transpose()), J(F.determinant()), log_J(std::log(J)) {}
};

// Eigenvalues of a symmetric 3x3 matrix, ascending, by the closed-form solver
// (cheap enough for a per-particle time-step bound; relative accuracy ~1e-12 on
// well separated eigenvalues, lower on near-repeated ones).
inline Vec3 symmetric_eigenvalues(const Mat3& A) {
  Eigen::SelfAdjointEigenSolver<Mat3> solver;
  solver.computeDirect(A, Eigen::EigenvaluesOnly);
  return solver.eigenvalues();
}

}  // namespace rkpm::materials
