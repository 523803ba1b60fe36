#include "rkpm/rk/row_scatter.hpp"

#include <algorithm>

namespace rkpm::rk {

namespace {
// The block [begin, end) of `n` items that thread t of `threads` gets, as OpenMP's
// schedule(static) without a chunk would give it.
std::pair<Index, Index> static_block(Index n, int t, int threads) {
  const Index base = n / threads, extra = n % threads;
  const Index begin = t * base + std::min<Index>(t, extra);
  return {begin, begin + base + (t < extra ? 1 : 0)};
}
}  // namespace

void RowScatter::plan(Index first_row, Index end_row, Index n_columns, const std::vector<Pattern>& patterns,
                      int threads, int channels) {
  threads_ = std::max(threads, 1);
  channels_ = channels;
  n_columns_ = n_columns;
  row_begin_.assign(static_cast<std::size_t>(threads_) + 1, 0);
  col_lo_.assign(static_cast<std::size_t>(threads_), n_columns);
  col_hi_.assign(static_cast<std::size_t>(threads_), 0);
  for (int t = 0; t < threads_; ++t) {
    auto [begin, end] = static_block(end_row - first_row, t, threads_);
    begin += first_row;
    end += first_row;
    row_begin_[static_cast<std::size_t>(t)] = begin;
    row_begin_[static_cast<std::size_t>(t) + 1] = end;
    Index lo = n_columns, hi = 0;
    for (Index r = begin; r < end; ++r) {
      if (r < n_columns) {  // the row's own particle (stabilization: row L acts on d_L)
        lo = std::min(lo, r);
        hi = std::max(hi, r + 1);
      }
      for (const auto& p : patterns)
        for (Index k = (*p.row_offset)[r]; k < (*p.row_offset)[r + 1]; ++k) {
          lo = std::min(lo, (*p.col)[k]);
          hi = std::max(hi, (*p.col)[k] + 1);
        }
    }
    col_lo_[static_cast<std::size_t>(t)] = std::min(lo, hi);
    col_hi_[static_cast<std::size_t>(t)] = hi;
  }
  buffers_.assign(static_cast<std::size_t>(threads_ * channels_), std::vector<Vec3>(n_columns, Vec3::Zero()));
}

void RowScatter::clear(int t) {
  const auto lo = col_lo_[static_cast<std::size_t>(t)], hi = col_hi_[static_cast<std::size_t>(t)];
  for (int c = 0; c < channels_; ++c) std::fill(buffer(t, c) + lo, buffer(t, c) + hi, Vec3::Zero());
}

Vec3 RowScatter::thread_sum(int channel, Index I) const {
  Vec3 sum = Vec3::Zero();
  for (int s = 0; s < threads_; ++s)
    if (I >= col_lo_[static_cast<std::size_t>(s)] && I < col_hi_[static_cast<std::size_t>(s)])
      sum += buffers_[static_cast<std::size_t>(s * channels_ + channel)][static_cast<std::size_t>(I)];
  return sum;
}

void RowScatter::reduce(int t, int channel, double scale, std::vector<Vec3>& out) const {
  const auto [begin, end] = static_block(n_columns_, t, threads_);
  for (Index I = begin; I < end; ++I) out[static_cast<std::size_t>(I)] = scale * thread_sum(channel, I);
}

void RowScatter::reduce_add(int t, int channel, double scale, std::vector<Vec3>& out) const {
  const auto [begin, end] = static_block(n_columns_, t, threads_);
  for (Index I = begin; I < end; ++I) out[static_cast<std::size_t>(I)] += scale * thread_sum(channel, I);
}

std::size_t RowScatter::bytes() const {
  std::size_t b = (row_begin_.size() + col_lo_.size() + col_hi_.size()) * sizeof(Index);
  for (const auto& v : buffers_) b += v.size() * sizeof(Vec3);
  return b;
}

}  // namespace rkpm::rk
