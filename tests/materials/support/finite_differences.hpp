// Finite-difference references for the material tests: gradients of a scalar
// energy and the acoustic tensor from differences of the stress.
#pragma once

#include "rkpm/common/types.hpp"

#include <Eigen/Eigenvalues>

namespace rkpm::materials::testing {

// Fourth-order central difference d f / dx of a scalar function of one variable.
template <class Function>
double derivative(const Function& f, double x, double step) {
  return (8.0 * (f(x + step) - f(x - step)) - (f(x + 2 * step) - f(x - 2 * step))) / (12.0 * step);
}

// d f / dA for f: Matrix -> double, component by component (fourth order).
template <class Matrix, class Function>
Matrix gradient(const Function& f, const Matrix& A, double step) {
  Matrix grad;
  for (Eigen::Index k = 0; k < A.size(); ++k) {
    const auto f_at = [&](double value) {
      Matrix shifted = A;
      shifted(k) = value;
      return f(shifted);
    };
    grad(k) = derivative(f_at, A(k), step);
  }
  return grad;
}

// Numerical acoustic tensor Q(N)_ik = dP_iJ/dF_kL N_J N_L from differences of
// the first Piola-Kirchhoff stress along F + e m (x) N (fourth order).
template <class Stress>
Mat3 acoustic_tensor(const Stress& first_piola, const Mat3& F, const Vec3& N, double step) {
  Mat3 Q;
  for (int k = 0; k < 3; ++k) {
    const Mat3 direction = Vec3::Unit(k) * N.transpose();
    const auto P_at = [&](double e) -> Mat3 { return first_piola(F + e * direction); };
    const Mat3 dP = (8.0 * (P_at(step) - P_at(-step)) - (P_at(2 * step) - P_at(-2 * step))) / (12.0 * step);
    Q.col(k) = dP * N;
  }
  return Q;
}

inline double largest_eigenvalue_symmetrised(const Mat3& Q) {
  const Mat3 S = 0.5 * (Q + Q.transpose());
  return Eigen::SelfAdjointEigenSolver<Mat3>(S).eigenvalues()[2];
}

}  // namespace rkpm::materials::testing
