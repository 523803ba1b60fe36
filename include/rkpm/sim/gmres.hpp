// Restarted GMRES (Saad & Schultz 1986) with a diagonal right preconditioner, for
// operators known only by their action: the Newton-Krylov relaxation applies the
// Jacobian by a difference of two force evaluations (newton_krylov.hpp), so each
// iteration costs one application and nothing is assembled.
#pragma once

#include <Eigen/Core>

#include <functional>

namespace rkpm::sim {

struct GmresSettings {
  double relative_tol = 1e-2;  // stop when |b - A z| <= relative_tol |b|
  int max_iterations = 300;    // applications of A, the restarts' residuals included
  int restart = 60;            // Krylov vectors kept before a restart
};

struct GmresResult {
  int iterations = 0;            // applications of A
  double relative_residual = 1;  // |b - A z| / |b|, from the least-squares problem (exact in exact arithmetic)
  bool converged = false;
};

// Solves A z = b approximately, z = P w with P = diag(preconditioner): GMRES minimises
// |b - A P w| over the Krylov space of A P. The residual it reports is that of its
// least-squares problem, the true one for a linear A in exact arithmetic (an A made by
// differences of forces is linear only to its difference error).
// `apply(v, out)` sets out = A v. Deterministic: every sum runs in one order.
GmresResult gmres(const std::function<void(const Eigen::VectorXd&, Eigen::VectorXd&)>& apply, const Eigen::VectorXd& b,
                  const Eigen::VectorXd& preconditioner, const GmresSettings& settings, Eigen::VectorXd& z);

}  // namespace rkpm::sim
