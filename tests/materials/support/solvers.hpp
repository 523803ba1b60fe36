// Small nonlinear solvers for the material tests: Newton root finding with a
// finite-difference Jacobian, and a Levenberg-Marquardt minimiser driven by an
// exact gradient (here: components of P) and a finite-difference Hessian.
#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rkpm::materials::testing {

using Vector = Eigen::VectorXd;
using Matrix = Eigen::MatrixXd;

// Central-difference Jacobian of a vector function.
template <class Function>
Matrix jacobian(const Function& f, const Vector& x, double step) {
  const Eigen::Index n = x.size();
  const Vector f0 = f(x);
  Matrix Jm(f0.size(), n);
  for (Eigen::Index j = 0; j < n; ++j) {
    Vector xp = x, xm = x;
    xp[j] += step;
    xm[j] -= step;
    Jm.col(j) = (f(xp) - f(xm)) / (2.0 * step);
  }
  return Jm;
}

// Newton's method; a step is halved only while it lands where the residual is
// not finite (e.g. det F <= 0). Full steps otherwise: a monotone-|r| line search
// stalls on the stiff near-incompressible systems these tests solve, while the
// plain iteration converges quadratically from the undeformed start.
// Throws if it does not reach |r| <= tolerance.
template <class Residual>
Vector solve_roots(const Residual& r, Vector x, double tolerance, int max_iterations = 100) {
  Vector res = r(x);
  for (int it = 0; it < max_iterations && res.norm() > tolerance; ++it) {
    const Vector dx = jacobian(r, x, 1e-7).fullPivLu().solve(-res);
    double t = 1.0;
    Vector trial = x + dx;
    Vector trial_res = r(trial);
    while (!trial_res.allFinite() && t > 1e-6) {
      t *= 0.5;
      trial = x + t * dx;
      trial_res = r(trial);
    }
    x = trial;
    res = trial_res;
  }
  if (!(res.norm() <= tolerance))
    throw std::runtime_error("solve_roots: Newton did not converge, |r| = " + std::to_string(res.norm()) +
                             " at x[0] = " + std::to_string(x[0]));
  return x;
}

// Scalar Newton (central-difference derivative) with step halving on |f|.
template <class Function>
double solve_root(const Function& f, double x, double tolerance, int max_iterations = 100) {
  double value = f(x);
  for (int it = 0; it < max_iterations && std::abs(value) > tolerance; ++it) {
    const double step = 1e-7 * std::max(1.0, std::abs(x));
    const double dx = -value * 2.0 * step / (f(x + step) - f(x - step));
    double t = 1.0, trial = x + dx, trial_value = f(trial);
    while (!(std::abs(trial_value) < std::abs(value)) && t > 1e-6) {
      t *= 0.5;
      trial = x + t * dx;
      trial_value = f(trial);
    }
    x = trial;
    value = trial_value;
  }
  if (!(std::abs(value) <= tolerance)) throw std::runtime_error("solve_root: Newton did not converge");
  return x;
}

struct Minimum {
  Vector x;
  double value;
  double gradient_norm;
};

// Levenberg-Marquardt minimisation of `energy` with exact `gradient`; the
// damping makes it a gradient descent far from the minimum and Newton near it.
template <class Energy, class Gradient>
Minimum minimise(const Energy& energy, const Gradient& gradient, Vector x, double gradient_tolerance,
                 int max_iterations = 500) {
  double damping = 1e-3;
  double value = energy(x);
  Vector g = gradient(x);
  for (int it = 0; it < max_iterations && g.norm() > gradient_tolerance; ++it) {
    Matrix H = jacobian(gradient, x, 1e-7);
    H = 0.5 * (H + H.transpose());
    const double scale = std::max(1.0, H.diagonal().cwiseAbs().maxCoeff());
    for (int attempt = 0; attempt < 60; ++attempt) {
      const Matrix shifted = H + damping * scale * Matrix::Identity(x.size(), x.size());
      const Vector trial = x + shifted.ldlt().solve(-g);
      const double trial_value = energy(trial);
      const Vector trial_g = gradient(trial);
      // Accept on energy decrease, or (at round-off level) on a smaller gradient.
      const bool better = trial_value < value ||
                          (trial_value <= value + 1e-14 * (1.0 + std::abs(value)) && trial_g.norm() < g.norm());
      if (better) {
        x = trial;
        value = trial_value;
        g = trial_g;
        damping = std::max(damping / 4.0, 1e-12);
        break;
      }
      damping *= 4.0;
    }
  }
  if (!(g.norm() <= gradient_tolerance)) throw std::runtime_error("minimise: did not converge");
  return {x, value, g.norm()};
}

}  // namespace rkpm::materials::testing
