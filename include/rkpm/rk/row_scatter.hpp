// Deterministic scatter of per-row contributions to particles, for the transposed
// products of nodal integration (f_I = sum_L V_L P_L b_I(X_L), the stabilization's
// N^T W r).
//
// Why a scatter: computed as a gather over the transposed operator, the force reads
// every entry of b_I(X_L) a second time per step, through an index indirection, in an
// order unrelated to how the entries are stored. As a scatter from row L it reuses the
// row the deformation gradient F_L has just read: the operator streams through memory
// once per step (see docs/performance.md).
//
// Why no race: each thread owns a fixed contiguous block of rows (the same split every
// step) and adds into a buffer of its own; only the columns its rows touch are zeroed
// and summed. The buffers are then added in thread order, so the result depends on the
// thread count only, never on scheduling, and no atomics are needed. With one thread
// the sum for each particle runs over its rows in increasing order, exactly as the
// transposed gather did.
#pragma once

#include "rkpm/common/types.hpp"

#include <vector>

namespace rkpm::rk {

class RowScatter {
 public:
  // Splits rows [0, n_rows) into `threads` contiguous blocks and records, for each
  // block, the range of columns its rows reference in any of the given patterns (each
  // a CSR row_offset/col pair over the same rows) or as the row's own particle.
  struct Pattern {
    const std::vector<Index>* row_offset;
    const std::vector<Index>* col;
  };
  void plan(Index n_rows, Index n_columns, const std::vector<Pattern>& patterns, int threads, int channels) {
    plan(0, n_rows, n_columns, patterns, threads, channels);
  }
  // The same over rows [first_row, end_row) only: a rank of a distributed run
  // evaluates the rows it owns.
  void plan(Index first_row, Index end_row, Index n_columns, const std::vector<Pattern>& patterns, int threads,
            int channels);

  bool planned_for(int threads) const { return threads_ == threads; }
  int threads() const { return threads_; }
  Index row_begin(int t) const { return row_begin_[static_cast<std::size_t>(t)]; }
  Index row_end(int t) const { return row_begin_[static_cast<std::size_t>(t) + 1]; }

  // Thread t's buffer for one channel (one output field), indexed by column. Call
  // `clear` from thread t before adding into it.
  Vec3* buffer(int t, int channel) { return buffers_[static_cast<std::size_t>(t * channels_ + channel)].data(); }
  void clear(int t);

  // out[I] = scale * sum over threads of buffer(t, channel)[I], for I in the static
  // block of columns of the calling thread (call inside the same parallel region,
  // after a barrier, from every thread).
  void reduce(int t, int channel, double scale, std::vector<Vec3>& out) const;
  // The same, added to out: out[I] += scale * sum over threads.
  void reduce_add(int t, int channel, double scale, std::vector<Vec3>& out) const;

  std::size_t bytes() const;

 private:
  Vec3 thread_sum(int channel, Index I) const;

  int threads_ = 0;
  int channels_ = 0;
  Index n_columns_ = 0;
  std::vector<Index> row_begin_;              // threads + 1
  std::vector<Index> col_lo_, col_hi_;        // columns touched by each block: [lo, hi)
  std::vector<std::vector<Vec3>> buffers_;    // threads x channels, n_columns each
};

}  // namespace rkpm::rk
