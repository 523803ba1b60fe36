#include "rkpm/sim/gmres.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <vector>

namespace rkpm::sim {

GmresResult gmres(const std::function<void(const Eigen::VectorXd&, Eigen::VectorXd&)>& apply, const Eigen::VectorXd& b,
                  const Eigen::VectorXd& preconditioner, const GmresSettings& settings, Eigen::VectorXd& z) {
  const Eigen::Index n = b.size();
  const int m = std::max(1, settings.restart);
  GmresResult result;
  z = Eigen::VectorXd::Zero(n);
  const double b_norm = b.norm();
  if (b_norm == 0.0) {
    result.relative_residual = 0.0;
    result.converged = true;
    return result;
  }
  const double target = settings.relative_tol * b_norm;
  std::vector<Eigen::VectorXd> basis(static_cast<std::size_t>(m) + 1);
  Eigen::MatrixXd hessenberg(m + 1, m);
  Eigen::VectorXd cosines(m), sines(m), g(m + 1);
  Eigen::VectorXd r = b, w(n), applied(n);
  double beta = b_norm;
  while (true) {
    basis[0] = r / beta;
    g.setZero();
    g[0] = beta;
    hessenberg.setZero();
    int k = 0;  // columns made in this cycle
    bool breakdown = false;
    while (k < m && result.iterations < settings.max_iterations) {
      w = preconditioner.cwiseProduct(basis[static_cast<std::size_t>(k)]);
      apply(w, applied);
      ++result.iterations;
      // Modified Gram-Schmidt, twice: a Krylov basis of an ill-conditioned operator
      // loses orthogonality in one pass.
      for (int pass = 0; pass < 2; ++pass)
        for (int i = 0; i <= k; ++i) {
          const double h = applied.dot(basis[static_cast<std::size_t>(i)]);
          hessenberg(i, k) += h;
          applied -= h * basis[static_cast<std::size_t>(i)];
        }
      const double next = applied.norm();
      hessenberg(k + 1, k) = next;
      // The earlier rotations, then the one that zeroes the new subdiagonal entry.
      for (int i = 0; i < k; ++i) {
        const double a = hessenberg(i, k), c = hessenberg(i + 1, k);
        hessenberg(i, k) = cosines[i] * a + sines[i] * c;
        hessenberg(i + 1, k) = -sines[i] * a + cosines[i] * c;
      }
      const double a = hessenberg(k, k), c = hessenberg(k + 1, k);
      const double rho = std::hypot(a, c);
      if (!(rho > 0.0)) {
        // A `apply` that maps the new direction to the span of the earlier ones: the
        // column adds nothing (and would divide by zero); the cycle ends with k columns.
        hessenberg.col(k).setZero();
        breakdown = true;
        break;
      }
      cosines[k] = a / rho;
      sines[k] = c / rho;
      hessenberg(k, k) = rho;
      hessenberg(k + 1, k) = 0.0;
      g[k + 1] = -sines[k] * g[k];
      g[k] = cosines[k] * g[k];
      ++k;
      // A vanishing new direction: the Krylov space is invariant and holds the solution.
      breakdown = !(next > 1e-14 * rho);
      if (!breakdown) basis[static_cast<std::size_t>(k)] = applied / next;
      if (std::abs(g[k]) <= target || breakdown) break;
    }
    if (k == 0) break;
    // The least-squares solution of the cycle: back substitution in the rotated Hessenberg.
    const Eigen::VectorXd y = hessenberg.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
    Eigen::VectorXd step = Eigen::VectorXd::Zero(n);
    for (int i = 0; i < k; ++i) step += y[i] * basis[static_cast<std::size_t>(i)];
    z += preconditioner.cwiseProduct(step);
    result.relative_residual = std::abs(g[k]) / b_norm;
    if (std::abs(g[k]) <= target || breakdown || result.iterations >= settings.max_iterations) break;
    // Restart from the true residual (one more application).
    apply(z, applied);
    ++result.iterations;
    r = b - applied;
    beta = r.norm();
    result.relative_residual = beta / b_norm;
    if (beta <= target) break;
  }
  result.converged = result.relative_residual <= settings.relative_tol;
  return result;
}

}  // namespace rkpm::sim
