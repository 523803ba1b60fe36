// The constraint system's solver in parts (sim/integration/constraint_solver.hpp): one
// part below 2 kPartSize particles, the single LU's bits; above, parts coupled through a
// separator that solve A x = b and A^T y = b to round-off.
#include "sim/integration/constraint_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace rkpm::sim {
namespace {

using SparseMatrix = ConstraintSolver::SparseMatrix;

// An n x n face of particles numbered row by row, each coupled to those within two
// spacings, with values like a kernel's (largest on the diagonal) and not symmetric:
// the pattern of Lambda_CC on a clamped face.
SparseMatrix face_matrix(int n) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int di = -2; di <= 2; ++di)
        for (int dj = -2; dj <= 2; ++dj) {
          const int k = i + di, l = j + dj;
          const double r = std::hypot(di, dj);
          if (k < 0 || k >= n || l < 0 || l >= n || r >= 2.5) continue;
          const double value = (r == 0.0 ? 1.0 : 0.08 * (2.5 - r)) * (1.0 + 0.3 * std::sin(1.7 * i + 0.9 * l));
          t.emplace_back(i * n + j, k * n + l, value);
        }
  SparseMatrix A(n * n, n * n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

Eigen::MatrixXd right_hand_sides(Eigen::Index m, int columns) {
  Eigen::MatrixXd b(m, columns);
  for (Eigen::Index i = 0; i < m; ++i)
    for (int c = 0; c < columns; ++c) b(i, c) = std::cos(0.37 * static_cast<double>(i) + c);
  return b;
}

TEST(ConstraintSolver, BelowTwoPartsItIsTheSingleLUBitForBit) {
  const SparseMatrix A = face_matrix(40);  // 1,600 < 2 x 1,024
  ConstraintSolver solver;
  ASSERT_TRUE(solver.factor(A));
  EXPECT_EQ(solver.parts(), 1);
  EXPECT_EQ(solver.separator_size(), 0);
  Eigen::SparseLU<SparseMatrix> lu;
  lu.compute(A);
  const Eigen::MatrixXd b = right_hand_sides(A.rows(), 6);
  EXPECT_EQ(solver.solve(b), Eigen::MatrixXd(lu.solve(b)));
  EXPECT_EQ(solver.solve_transposed(b), Eigen::MatrixXd(lu.transpose().solve(b)));
}

TEST(ConstraintSolver, PartsCoupledThroughTheSeparatorSolveBothSystems) {
  for (const int n : {48, 66}) {  // 2,304 and 4,356 particles: 2 and 4 parts
    const SparseMatrix A = face_matrix(n);
    ConstraintSolver solver;
    ASSERT_TRUE(solver.factor(A));
    EXPECT_EQ(solver.parts(), n == 48 ? 2 : 4);
    // A cut between rows of the face: the two rows on each side of it that reach across.
    EXPECT_GT(solver.separator_size(), 0);
    EXPECT_LE(solver.separator_size(), 4 * n * (solver.parts() - 1) + 8);
    const Eigen::MatrixXd b = right_hand_sides(A.rows(), 3);
    const Eigen::MatrixXd x = solver.solve(b);
    const Eigen::MatrixXd y = solver.solve_transposed(b);
    EXPECT_LT((A * x - b).cwiseAbs().maxCoeff(), 1e-13) << n;
    EXPECT_LT((SparseMatrix(A.transpose()) * y - b).cwiseAbs().maxCoeff(), 1e-13) << n;
    Eigen::SparseLU<SparseMatrix> lu;
    lu.compute(A);
    EXPECT_LT((x - Eigen::MatrixXd(lu.solve(b))).cwiseAbs().maxCoeff(), 1e-12) << n;
  }
}

TEST(ConstraintSolver, ASingularSystemIsReported) {
  SparseMatrix A = face_matrix(48);
  for (SparseMatrix::InnerIterator it(A, 7); it; ++it) it.valueRef() = 0.0;  // a zero column
  ConstraintSolver solver;
  EXPECT_FALSE(solver.factor(A));
}

}  // namespace
}  // namespace rkpm::sim
