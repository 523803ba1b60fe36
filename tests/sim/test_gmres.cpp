// GMRES (sim/gmres.hpp), the linear solver of the Newton-Krylov finish, against a
// direct solve of dense systems.
#include "rkpm/sim/gmres.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <random>

namespace rkpm::sim {
namespace {

// A nonsymmetric matrix with a spread diagonal (1 to 1e4, as the particles' stiffness
// spreads) and coupling of a tenth of it: the diagonal preconditioner leaves a
// well-conditioned operator.
Eigen::MatrixXd spread_matrix(int n, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd a(n, n);
  for (int i = 0; i < n; ++i) {
    const double diagonal = std::pow(1e4, static_cast<double>(i) / (n - 1));
    for (int j = 0; j < n; ++j) a(i, j) = 0.1 * diagonal * uniform(random) / std::sqrt(static_cast<double>(n));
    a(i, i) += diagonal;
  }
  return a;
}

GmresResult solve(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, const Eigen::VectorXd& preconditioner,
                  const GmresSettings& settings, Eigen::VectorXd& z, int& applications) {
  applications = 0;
  return gmres(
      [&](const Eigen::VectorXd& v, Eigen::VectorXd& out) {
        ++applications;
        out = a * v;
      },
      b, preconditioner, settings, z);
}

TEST(Gmres, ReachesItsToleranceWithTheTrueResidualItReports) {
  const int n = 120;
  const Eigen::MatrixXd a = spread_matrix(n, 7);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  const Eigen::VectorXd preconditioner = a.diagonal().cwiseInverse();
  for (int restart : {8, 200}) {
    GmresSettings settings;
    settings.relative_tol = 1e-10;
    settings.restart = restart;
    Eigen::VectorXd z;
    int applications = 0;
    const GmresResult r = solve(a, b, preconditioner, settings, z, applications);
    const double true_residual = (b - a * z).norm() / b.norm();
    const Eigen::VectorXd exact = a.partialPivLu().solve(b);
    EXPECT_TRUE(r.converged) << "restart " << restart;
    EXPECT_LE(true_residual, 1.01e-10) << "restart " << restart;
    EXPECT_NEAR(r.relative_residual, true_residual, 1e-12) << "restart " << restart;
    EXPECT_LT((z - exact).norm() / exact.norm(), 1e-8) << "restart " << restart;
    EXPECT_EQ(r.iterations, applications) << "every application of A is counted";
  }
}

// Without the preconditioner the spread diagonal makes the operator ill-conditioned
// (1e4), and GMRES needs many more iterations: the preconditioner is what works.
TEST(Gmres, TheDiagonalPreconditionerCutsTheIterations) {
  const int n = 120;
  const Eigen::MatrixXd a = spread_matrix(n, 11);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
  GmresSettings settings;
  settings.relative_tol = 1e-8;
  settings.restart = 30;
  settings.max_iterations = 2000;
  Eigen::VectorXd z;
  int applications = 0;
  const GmresResult with = solve(a, b, a.diagonal().cwiseInverse(), settings, z, applications);
  const GmresResult without = solve(a, b, Eigen::VectorXd::Ones(n), settings, z, applications);
  std::printf("GMRES(30) to 1e-8 on a 120 x 120 system: %d iterations with the diagonal preconditioner, %d without\n",
              with.iterations, without.iterations);
  EXPECT_TRUE(with.converged);
  EXPECT_LT(10 * with.iterations, without.iterations);
}

// An iteration limit stops the solve with the residual reached, not a converged flag.
TEST(Gmres, StopsAtTheIterationLimitAndSaysSo) {
  const int n = 120;
  const Eigen::MatrixXd a = spread_matrix(n, 3);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
  GmresSettings settings;
  settings.relative_tol = 1e-14;
  settings.max_iterations = 5;
  Eigen::VectorXd z;
  int applications = 0;
  const GmresResult r = solve(a, b, Eigen::VectorXd::Ones(n), settings, z, applications);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations, 5);
  EXPECT_GT(r.relative_residual, 1e-14);
  EXPECT_LT(r.relative_residual, 1.0);
  EXPECT_NEAR(r.relative_residual, (b - a * z).norm() / b.norm(), 1e-12);
}

TEST(Gmres, AZeroRightHandSideGivesZero) {
  const Eigen::MatrixXd a = spread_matrix(10, 5);
  Eigen::VectorXd z = Eigen::VectorXd::Ones(10);
  int applications = 0;
  const GmresResult r =
      solve(a, Eigen::VectorXd::Zero(10), Eigen::VectorXd::Ones(10), GmresSettings{}, z, applications);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(applications, 0);
  EXPECT_EQ(z.norm(), 0.0);
}

}  // namespace
}  // namespace rkpm::sim
