#include "sim/integration/constraint_solver.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace rkpm::sim {

namespace {

using SparseMatrix = ConstraintSolver::SparseMatrix;
using Triplets = std::vector<Eigen::Triplet<double>>;

// The rows and columns of A listed in `rows` and `cols` (positions in A, ascending):
// position -1 in the maps drops an index.
SparseMatrix block(const SparseMatrix& A, const std::vector<Eigen::Index>& row_of,
                   const std::vector<Eigen::Index>& col_of, Eigen::Index rows, Eigen::Index cols) {
  Triplets t;
  for (Eigen::Index j = 0; j < A.outerSize(); ++j) {
    if (col_of[static_cast<std::size_t>(j)] < 0) continue;
    for (SparseMatrix::InnerIterator it(A, j); it; ++it)
      if (row_of[static_cast<std::size_t>(it.row())] >= 0)
        t.emplace_back(row_of[static_cast<std::size_t>(it.row())], col_of[static_cast<std::size_t>(j)], it.value());
  }
  SparseMatrix B(rows, cols);
  B.setFromTriplets(t.begin(), t.end());
  return B;
}

std::unique_ptr<Eigen::SparseLU<SparseMatrix>> factored(const SparseMatrix& A) {
  auto lu = std::make_unique<Eigen::SparseLU<SparseMatrix>>();
  lu->compute(A);
  if (lu->info() != Eigen::Success) return nullptr;
  return lu;
}

}  // namespace

bool ConstraintSolver::factor(const SparseMatrix& A) {
  parts_.clear();
  separator_.clear();
  schur_lu_.reset();
  const Eigen::Index m = A.rows();
  Eigen::Index K = 1;
  while (m / (2 * K) >= kPartSize) K *= 2;
  std::vector<Eigen::Index> part_of(static_cast<std::size_t>(m));
  for (Eigen::Index k = 0; k < K; ++k) {
    Part p;
    p.begin = k * m / K;
    p.end = (k + 1) * m / K;
    for (Eigen::Index i = p.begin; i < p.end; ++i) part_of[static_cast<std::size_t>(i)] = k;
    parts_.push_back(std::move(p));
  }
  // The separator: every particle coupled to another part, by a row or a column.
  std::vector<char> on_separator(static_cast<std::size_t>(m), 0);
  for (Eigen::Index j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it)
      if (part_of[static_cast<std::size_t>(it.row())] != part_of[static_cast<std::size_t>(j)])
        on_separator[static_cast<std::size_t>(it.row())] = on_separator[static_cast<std::size_t>(j)] = 1;
  std::vector<Eigen::Index> separator_index(static_cast<std::size_t>(m), -1);
  for (Eigen::Index i = 0; i < m; ++i)
    if (on_separator[static_cast<std::size_t>(i)]) {
      separator_index[static_cast<std::size_t>(i)] = static_cast<Eigen::Index>(separator_.size());
      separator_.push_back(i);
    }
  const auto s = static_cast<Eigen::Index>(separator_.size());
  const auto singular = [&] {
    parts_.clear();
    separator_.clear();
    return false;
  };

  // Sigma = A_SS - sum_k A_Sk A_kk^-1 A_kS, summed in the order of k (the same on every rank).
  Eigen::MatrixXd sigma = Eigen::MatrixXd(block(A, separator_index, separator_index, s, s));
  for (auto& p : parts_) {
    std::vector<Eigen::Index> interior_index(static_cast<std::size_t>(m), -1);
    for (Eigen::Index i = p.begin; i < p.end; ++i)
      if (!on_separator[static_cast<std::size_t>(i)]) {
        interior_index[static_cast<std::size_t>(i)] = static_cast<Eigen::Index>(p.interior.size());
        p.interior.push_back(i);
      }
    const auto n = static_cast<Eigen::Index>(p.interior.size());
    p.lu = factored(block(A, interior_index, interior_index, n, n));
    if (!p.lu) return singular();
    p.to_separator = block(A, interior_index, separator_index, n, s);
    p.from_separator = block(A, separator_index, interior_index, s, n);
    if (s == 0) continue;
    const Eigen::MatrixXd reach = p.lu->solve(Eigen::MatrixXd(p.to_separator));  // A_kk^-1 A_kS
    sigma -= p.from_separator * reach;
  }
  if (s > 0) {
    schur_lu_ = factored(sigma.sparseView(0.0));
    if (!schur_lu_) return singular();
  }
  return true;
}

void ConstraintSolver::distribute(const par::Comm& comm) {
  comm_ = &comm;
  const auto K = static_cast<std::int64_t>(parts_.size());
  part_rank_.resize(parts_.size());
  for (std::int64_t k = 0; k < K; ++k) part_rank_[static_cast<std::size_t>(k)] = static_cast<int>(k * comm.size() / K);
}

std::vector<double> ConstraintSolver::gather_parts(const std::vector<double>& mine) const {
  if (comm_ == nullptr || !comm_->parallel()) return mine;
  return comm_->gather(mine);
}

Eigen::MatrixXd ConstraintSolver::solve_any(const Eigen::MatrixXd& b, bool transposed) const {
  const Eigen::Index c = b.cols();
  Eigen::MatrixXd x(b.rows(), c);
  const auto local = [&](const Part& p, const Eigen::MatrixXd& rhs) -> Eigen::MatrixXd {
    return transposed ? Eigen::MatrixXd(p.lu->transpose().solve(rhs)) : Eigen::MatrixXd(p.lu->solve(rhs));
  };
  const auto rows_of = [&](const std::vector<Eigen::Index>& positions) {
    Eigen::MatrixXd r(static_cast<Eigen::Index>(positions.size()), c);
    for (std::size_t i = 0; i < positions.size(); ++i) r.row(static_cast<Eigen::Index>(i)) = b.row(positions[i]);
    return r;
  };
  // One part: every rank solves it (no split, no exchange): the single LU.
  if (parts_.size() == 1) {
    const Eigen::MatrixXd y = local(parts_[0], rows_of(parts_[0].interior));
    for (std::size_t i = 0; i < parts_[0].interior.size(); ++i) x.row(parts_[0].interior[i]) = y.row(static_cast<Eigen::Index>(i));
    return x;
  }
  const auto s = static_cast<Eigen::Index>(separator_.size());
  // 1. Each of this rank's parts: y_k = A_kk^-1 b_k and its term A_Sk y_k of the separator's sum.
  std::vector<double> terms;
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    if (!mine(k)) continue;
    const Part& p = parts_[k];
    const Eigen::MatrixXd y = local(p, rows_of(p.interior));
    const Eigen::MatrixXd term =
        transposed ? Eigen::MatrixXd(p.to_separator.transpose() * y) : Eigen::MatrixXd(p.from_separator * y);
    terms.insert(terms.end(), term.data(), term.data() + term.size());
  }
  const std::vector<double> all_terms = gather_parts(terms);
  // 2. r_S = b_S - sum_k terms, in the order of k; x_S = Sigma^-1 r_S on every rank.
  Eigen::MatrixXd r = rows_of(separator_);
  for (std::size_t k = 0; k < parts_.size(); ++k)
    r -= Eigen::Map<const Eigen::MatrixXd>(all_terms.data() + static_cast<Eigen::Index>(k) * s * c, s, c);
  Eigen::MatrixXd x_s = r;  // no separator: parts that do not couple
  if (schur_lu_) x_s = transposed ? Eigen::MatrixXd(schur_lu_->transpose().solve(r)) : Eigen::MatrixXd(schur_lu_->solve(r));
  // 3. Each of this rank's parts: x_k = A_kk^-1 (b_k - A_kS x_S); then every part's on every rank.
  std::vector<double> values;
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    if (!mine(k)) continue;
    const Part& p = parts_[k];
    const Eigen::MatrixXd coupled =
        transposed ? Eigen::MatrixXd(p.from_separator.transpose() * x_s) : Eigen::MatrixXd(p.to_separator * x_s);
    const Eigen::MatrixXd xk = local(p, rows_of(p.interior) - coupled);
    values.insert(values.end(), xk.data(), xk.data() + xk.size());
  }
  const std::vector<double> all_values = gather_parts(values);
  std::size_t at = 0;
  for (const Part& p : parts_) {
    const auto n = static_cast<Eigen::Index>(p.interior.size());
    const Eigen::Map<const Eigen::MatrixXd> xk(all_values.data() + at, n, c);
    for (Eigen::Index i = 0; i < n; ++i) x.row(p.interior[static_cast<std::size_t>(i)]) = xk.row(i);
    at += static_cast<std::size_t>(n * c);
  }
  for (Eigen::Index i = 0; i < s; ++i) x.row(separator_[static_cast<std::size_t>(i)]) = x_s.row(i);
  return x;
}

}  // namespace rkpm::sim
