// Solves the essential boundary conditions' constraint system Lambda_CC x = b (and its
// transpose) so that ranks share the work of a step and every rank count gives the same
// bits.
//
// Why not one sparse LU on every rank: its cost follows the whole constrained surface,
// so a rank pays for all of it whatever its share (a clamped face that grows with the
// ranks makes each rank's solve grow too). Why not any split by ranks: the round-off
// would then depend on the rank count.
//
// How: C is cut into K parts, contiguous runs of C in particle order, K chosen from |C|
// alone (kPartSize), so the cut does not depend on the ranks. The separator S holds the
// particles coupled to another part (A_ij or A_ji nonzero); the rest of part k is its
// interior I_k. With the interiors first, the system is block-bordered:
//     [ A_II  A_IS ] [x_I]   [b_I]      A_II = diag(A_11, ..., A_KK),
//     [ A_SI  A_SS ] [x_S] = [b_S],
// and a solve is
//     y_k = A_kk^-1 b_k,   r_S = b_S - sum_k A_Sk y_k,   x_S = Sigma^-1 r_S,
//     x_k = A_kk^-1 (b_k - A_kS x_S),     Sigma = A_SS - sum_k A_Sk A_kk^-1 A_kS,
// the transpose alike with every block transposed. Each part's two solves run on one
// rank, the ranks taking equal runs of parts; the sum over k runs in the order of k on
// every rank (the parts' terms are gathered), and Sigma's solve is repeated everywhere
// (S is a few rows of particles along each cut). The factors are built alike on every
// rank. With K = 1 (|C| < 2 kPartSize) this is the single LU.
#pragma once

#include "rkpm/par/comm.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <memory>
#include <vector>

namespace rkpm::sim {

class ConstraintSolver {
 public:
  using SparseMatrix = Eigen::SparseMatrix<double>;

  // Parts of at least this many particles: K = the largest power of two with
  // |C| / K >= kPartSize (a power of two splits evenly over 2, 4, ... ranks).
  static constexpr Eigen::Index kPartSize = 1024;

  // Factors A = Lambda_CC (rows and columns in the order of C). Returns false (and
  // leaves the solver empty) when A, or a part's interior block, is singular.
  bool factor(const SparseMatrix& A);

  // On P ranks: part k is solved by rank floor(k P / K), so the ranks share the parts
  // evenly whoever owns their particles (every rank holds the whole right-hand side, and
  // a part's arithmetic is the same on any rank), and each rank's parts are a run of them.
  void distribute(const par::Comm& comm);

  Eigen::Index parts() const { return static_cast<Eigen::Index>(parts_.size()); }
  Eigen::Index separator_size() const { return static_cast<Eigen::Index>(separator_.size()); }

  // A^-1 b and A^-T b, whole, on every rank (collective when distributed).
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const { return solve_any(b, false); }
  Eigen::MatrixXd solve_transposed(const Eigen::MatrixXd& b) const { return solve_any(b, true); }

 private:
  struct Part {
    Eigen::Index begin = 0, end = 0;  // its run of C
    std::vector<Eigen::Index> interior;  // positions in C, ascending
    std::unique_ptr<Eigen::SparseLU<SparseMatrix>> lu;  // A_kk
    SparseMatrix to_separator;    // A_kS: |I_k| x |S|
    SparseMatrix from_separator;  // A_Sk: |S| x |I_k|
  };

  Eigen::MatrixXd solve_any(const Eigen::MatrixXd& b, bool transposed) const;
  bool mine(std::size_t k) const { return comm_ == nullptr || part_rank_[k] == comm_->rank(); }
  // Every rank's values for its parts, concatenated in the order of the parts (a rank
  // holds a run of them); the identity on one rank.
  std::vector<double> gather_parts(const std::vector<double>& mine) const;

  std::vector<Part> parts_;
  std::vector<Eigen::Index> separator_;  // positions in C, ascending
  std::unique_ptr<Eigen::SparseLU<SparseMatrix>> schur_lu_;  // Sigma (or A itself when K = 1)
  const par::Comm* comm_ = nullptr;
  std::vector<int> part_rank_;
};

}  // namespace rkpm::sim
