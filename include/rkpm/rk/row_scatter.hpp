// Deterministic scatter of per-row contributions to particles, for the transposed
// products of nodal integration (f_I = sum_L V_L P_L b_I(X_L), the stabilization's
// N^T W r) and for the transfer of point forces through the interpolation rows.
//
// Why a scatter: computed as a gather over the transposed operator, the force reads
// every entry of b_I(X_L) a second time per step, through an index indirection, in an
// order unrelated to how the entries are stored. As a scatter from row L it reuses the
// row the deformation gradient F_L has just read: the operator streams through memory
// once per step (see docs/verification/performance.md).
//
// Why no race: each thread owns a fixed contiguous block of rows (the same split every
// step) and adds into a buffer of its own; only the columns its rows touch are zeroed
// and summed.
//
// Why the same bits on any thread and rank count (the ordered plan): with one thread
// on one rank, particle I's sum runs over its rows in increasing order, each row's
// contributions in the order the row makes them. That is the reference order. A
// column whose contributions all come from one thread's block gets them in that order
// in the thread's buffer. A column that several blocks reach (a seam: rows of two
// threads, or of two ranks) would get partial sums added in another grouping, so the
// first thread to reach it adds its contributions in its buffer as usual, and the later
// threads record theirs one by one, each in its own segment; the fold then starts from
// the first thread's sum and adds the records in block order, which is row order: the
// same additions in the same order as one thread makes them. At a column shared with
// another rank the threads record too; the records of a ghost column are sent to its
// owner (`Links`), which folds them in rank order with its own: ranks own contiguous,
// increasing ranges of rows (par/partition.hpp). The lowest rank whose rows reach a
// shared column makes its first contributions, so its first thread there adds in
// place and sends the sum as one record, which starts the owner's fold. Seams are a
// thin layer at the block boundaries, so the recording costs little. The plan is
// checked at every fold: a row that made other contributions than it declared is an
// internal error.
#pragma once

#include "rkpm/common/types.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace rkpm::rk {

class RowScatter {
 public:
  // Splits rows [0, n_rows) into `threads` contiguous blocks and records, for each
  // block, the range of columns its rows reference in any of the given patterns (each
  // a CSR row_offset/col pair over the same rows) or as the row's own particle. The sum
  // at a column then depends on the thread count (partial sums added in thread order).
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

  // What the ordered plan needs from the other ranks (par::GhostExchange provides it):
  // this rank's ghosts grouped by owner and its own particles grouped by the ranks that
  // hold them, each group sorted, and two exchanges (send[p] to rank p, recv[p] from
  // it; the double exchange's receive sizes are known to both sides).
  struct Links {
    int rank = 0;
    Index owned_begin = 0, owned_end = 0;  // this rank's particles
    const std::vector<std::vector<Index>>* ghosts = nullptr;
    const std::vector<std::vector<Index>>* holders = nullptr;
    std::function<void(const std::vector<std::vector<std::int64_t>>&, std::vector<std::vector<std::int64_t>>&)>
        exchange_counts;
    std::function<void(const std::vector<std::vector<double>>&, std::vector<std::vector<double>>&)> exchange_values;
  };
  // The ordered plan (see the file comment): `columns(L, channel, emit)` calls
  // emit(I) for every contribution row L makes to channel `channel`, in the order the
  // pass makes them through `sink` below. `links` is null on one rank.
  using RowColumns = std::function<void(Index row, int channel, const std::function<void(Index)>& emit)>;
  void plan_ordered(Index first_row, Index end_row, Index n_columns, int threads, int channels,
                    const RowColumns& columns, const Links* links = nullptr);

  // The threads a `#pragma omp parallel num_threads(n)` region of a scatter's user will
  // get: omp_get_max_threads() capped by OMP_THREAD_LIMIT (a team smaller than the plan
  // would leave rows undone). Plan with this and open the region with it.
  static int team_threads();

  bool planned_for(int threads) const { return threads_ == threads; }
  bool planned_for(int threads, int channels) const { return threads_ == threads && channels_ == channels; }
  int threads() const { return threads_; }
  Index row_begin(int t) const { return row_begin_[static_cast<std::size_t>(t)]; }
  Index row_end(int t) const { return row_begin_[static_cast<std::size_t>(t) + 1]; }

  // Thread t's buffer for one channel (one output field), indexed by column. Call
  // `clear` from thread t before adding into it.
  Vec3* buffer(int t, int channel) { return buffers_[static_cast<std::size_t>(t * channels_ + channel)].data.get(); }
  void clear(int t);

  // Where row L of thread t puts its contributions to one channel: sink(I, c) adds c
  // at column I (or records it, at a seam). Rows must be visited in increasing order.
  class Sink {
   public:
    void operator()(Index I, const Vec3& c) const {
      if (slot_ != nullptr) {
        const Index s = slot_[I];
        if (s >= 0 && first_[s] != thread_) {
          records_[cursor_[s]++] = c;
          return;
        }
      }
      out_[I] += c;
    }
    // True when the row reaches a seam: each of its contributions must then be made.
    bool records() const { return slot_ != nullptr; }

   private:
    friend class RowScatter;
    Vec3* out_ = nullptr;
    const Index* slot_ = nullptr;  // null for a row that reaches no seam
    const int* first_ = nullptr;
    int thread_ = 0;
    Index* cursor_ = nullptr;
    Vec3* records_ = nullptr;
  };
  Sink sink(int t, int channel, Index row);
  // True when row L reaches a seam: its contributions must go through `sink`. The others
  // may add straight into buffer(t, channel), as `AddTo` does.
  bool seam_row(Index row) const {
    return !seam_row_.empty() && seam_row_[static_cast<std::size_t>(row - first_row_)] != 0;
  }
  struct AddTo {
    Vec3* out;
    void operator()(Index I, const Vec3& c) const { out[I] += c; }
  };

  // out[I] = scale * sum over threads of buffer(t, channel)[I], for I in the static
  // block of columns of the calling thread (call inside the same parallel region,
  // after a barrier, from every thread). Seams are left for `fold`.
  void reduce(int t, int channel, double scale, std::vector<Vec3>& out) const;
  // The same, added to out: out[I] += scale * sum over threads.
  void reduce_add(int t, int channel, double scale, std::vector<Vec3>& out) const;
  // The seams of an ordered plan, after `reduce` or `reduce_add` (outside the parallel
  // region, on every rank): the channel's records are exchanged with the other ranks,
  // and out[I] = (or +=) scale * the contributions in order. Only the columns this rank
  // owns are written.
  void fold(int channel, double scale, std::vector<Vec3>& out, bool add);

  std::size_t bytes() const;
  // Columns whose contributions are recorded, and records per pass (all channels).
  std::size_t seam_count() const { return seams_.size(); }
  std::size_t record_count() const;
  // Records this rank sends to the others per pass (all channels).
  std::size_t records_sent() const;

 private:
  Vec3 thread_sum(int channel, Index I) const;
  std::pair<Index, Index> reduce_block(int t) const;
  void split_rows(Index first_row, Index end_row);
  void allocate_buffers(Index n_columns);
  bool seam(Index I) const { return !slot_.empty() && slot_[static_cast<std::size_t>(I)] >= 0; }
  void exchange_records(int channel);
  std::vector<char> lowest_reaching_rank(const std::vector<Index>& reached_by) const;
  // True when this rank makes the first contributions to ghost g: their sum, kept in its
  // first thread's buffer, goes to the owner ahead of the records.
  bool sends_first_sum(Index g) const {
    return first_[static_cast<std::size_t>(slot_[static_cast<std::size_t>(g)])] >= 0;
  }

  int threads_ = 0;
  int channels_ = 0;
  Index n_columns_ = 0;
  std::vector<Index> row_begin_;              // threads + 1
  std::vector<Index> col_lo_, col_hi_;        // columns touched by each block: [lo, hi)
  // One thread's scratch for one channel. Left uninitialised (allocate_buffers says
  // why); a copy is a fresh buffer of the same length, since the contents are scratch
  // that `clear` resets before every pass.
  struct Scratch {
    std::unique_ptr<Vec3[]> data;
    std::size_t size = 0;
    explicit Scratch(std::size_t n) : data(new Vec3[n]), size(n) {}
    Scratch(const Scratch& other) : Scratch(other.size) {}
    Scratch& operator=(const Scratch& other) { return *this = Scratch(other.size); }
    Scratch(Scratch&&) noexcept = default;
    Scratch& operator=(Scratch&&) noexcept = default;
    Vec3& operator[](std::size_t i) { return data[i]; }
    const Vec3& operator[](std::size_t i) const { return data[i]; }
  };
  std::vector<Scratch> buffers_;              // threads x channels, n_columns each; valid in [col_lo, col_hi)

  // The ordered plan's seams.
  Index first_row_ = 0;
  std::vector<Index> slot_;                   // per column: its seam index, or -1
  std::vector<Index> seams_;                  // per seam: its column
  std::vector<char> owned_;                   // per seam: 1 when this rank owns the column
  // Per seam: the first thread that reaches it, which adds its contributions in its
  // buffer (their sum starts the fold, or is sent to the owner as its first record);
  // -1 at a column shared with a lower rank that reaches it, where every thread records.
  std::vector<int> first_;
  std::vector<std::uint8_t> seam_row_;        // per row from first_row_: 1 when it reaches a seam
  struct Channel {
    std::vector<Index> segment;               // seams + 1: each seam's records [segment[s], segment[s+1])
    std::vector<std::vector<Index>> start;    // threads + 1, per seam: where each thread's records start
                                              // (the last: where this rank's end)
    std::vector<std::vector<Index>> cursor;   // per thread, per seam: where its next record goes
    std::vector<Vec3> records;
    // Distributed: the records exchanged with each rank, per ghost or holder in group
    // order: where each group member's records sit in `records` and how many.
    std::vector<std::vector<Index>> send_at, send_count, recv_at, recv_count;
  };
  std::vector<Channel> ordered_;
  Links links_;
  bool linked_ = false;
  std::vector<std::vector<double>> send_, recv_;
};

}  // namespace rkpm::rk
