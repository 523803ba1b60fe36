#include "rkpm/rk/row_scatter.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <stdexcept>

namespace rkpm::rk {

namespace {
// The block [begin, end) of `n` items that thread t of `threads` gets, as OpenMP's
// schedule(static) without a chunk would give it.
std::pair<Index, Index> static_block(Index n, int t, int threads) {
  const Index base = n / threads, extra = n % threads;
  const Index begin = t * base + std::min<Index>(t, extra);
  return {begin, begin + base + (t < extra ? 1 : 0)};
}

constexpr Index kUntouched = -1;  // reached_by: no row of this rank reaches the column
constexpr Index kSeveral = -2;    // reached_by: rows of several threads reach it
}  // namespace

// Thread t's rows: block t of OpenMP's static schedule over [first_row, end_row).
void RowScatter::split_rows(Index first_row, Index end_row) {
  row_begin_.assign(static_cast<std::size_t>(threads_) + 1, first_row);
  for (int t = 0; t < threads_; ++t) {
    const auto [begin, end] = static_block(end_row - first_row, t, threads_);
    row_begin_[static_cast<std::size_t>(t)] = first_row + begin;
    row_begin_[static_cast<std::size_t>(t) + 1] = first_row + end;
  }
}

void RowScatter::plan(Index first_row, Index end_row, Index n_columns, const std::vector<Pattern>& patterns,
                      int threads, int channels) {
  threads_ = std::max(threads, 1);
  channels_ = channels;
  n_columns_ = n_columns;
  first_row_ = first_row;
  slot_.clear();
  seams_.clear();
  owned_.clear();
  seam_row_.clear();
  ordered_.clear();
  first_.clear();
  linked_ = false;
  split_rows(first_row, end_row);
  col_lo_.assign(static_cast<std::size_t>(threads_), n_columns);
  col_hi_.assign(static_cast<std::size_t>(threads_), 0);
  for (int t = 0; t < threads_; ++t) {
    Index lo = n_columns, hi = 0;
    for (Index r = row_begin(t); r < row_end(t); ++r) {
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
  allocate_buffers(n_columns);
}

void RowScatter::plan_ordered(Index first_row, Index end_row, Index n_columns, int threads, int channels,
                              const RowColumns& columns, const Links* links) {
  threads_ = std::max(threads, 1);
  channels_ = channels;
  n_columns_ = n_columns;
  first_row_ = first_row;
  linked_ = links != nullptr;
  links_ = linked_ ? *links : Links{};
  const auto nt = static_cast<std::size_t>(threads_);
  const auto n = static_cast<std::size_t>(n_columns);
  split_rows(first_row, end_row);
  col_lo_.assign(nt, n_columns);
  col_hi_.assign(nt, 0);

  // Seams: columns reached by the rows of two threads, and columns shared with another
  // rank (its ghosts, and its own particles that other ranks hold).
  slot_.assign(n, -1);
  std::vector<Index> reached_by(n, kUntouched), first_reach(n, kUntouched);
  for (int t = 0; t < threads_; ++t) {
    Index lo = n_columns, hi = 0;
    for (Index r = row_begin(t); r < row_end(t); ++r)
      for (int c = 0; c < channels_; ++c)
        columns(r, c, [&](Index I) {
          lo = std::min(lo, I);
          hi = std::max(hi, I + 1);
          auto& by = reached_by[static_cast<std::size_t>(I)];
          by = by == kUntouched || by == t ? t : kSeveral;
          auto& first = first_reach[static_cast<std::size_t>(I)];
          if (first == kUntouched) first = t;
        });
    col_lo_[static_cast<std::size_t>(t)] = std::min(lo, hi);
    col_hi_[static_cast<std::size_t>(t)] = hi;
  }
  for (std::size_t I = 0; I < n; ++I)
    if (reached_by[I] == kSeveral) slot_[I] = 0;
  std::vector<char> rank_shared(linked_ ? n : 0, 0);
  if (linked_) {
    for (const auto* groups : {links_.ghosts, links_.holders})
      for (const auto& group : *groups)
        for (Index I : group) {
          slot_[static_cast<std::size_t>(I)] = 0;
          rank_shared[static_cast<std::size_t>(I)] = 1;
        }
    for (std::size_t I = 0; I < n; ++I) {
      const auto i = static_cast<Index>(I);
      if (reached_by[I] != kUntouched && slot_[I] < 0 && (i < links_.owned_begin || i >= links_.owned_end))
        throw std::logic_error(fmt::format("ordered scatter: rank {} reaches particle {}, which it neither owns nor "
                                           "holds as a ghost", links_.rank, i));
    }
  }
  // At a particle several ranks share, the lowest rank whose rows reach it makes the
  // first contributions (ranks own increasing ranges of rows), so its first thread adds
  // in place there too and the sum goes out as one record.
  const std::vector<char> lowest = linked_ ? lowest_reaching_rank(reached_by) : std::vector<char>{};
  seams_.clear();
  owned_.clear();
  first_.clear();
  for (std::size_t I = 0; I < n; ++I)
    if (slot_[I] >= 0) {
      slot_[I] = static_cast<Index>(seams_.size());
      seams_.push_back(static_cast<Index>(I));
      const auto i = static_cast<Index>(I);
      owned_.push_back(!linked_ || (i >= links_.owned_begin && i < links_.owned_end) ? 1 : 0);
      first_.push_back(linked_ && rank_shared[I] != 0 && lowest[I] == 0 ? -1 : static_cast<int>(first_reach[I]));
    }
  const std::size_t ns = seams_.size();

  // The rows that reach a seam, and each thread's contributions to each seam.
  seam_row_.assign(static_cast<std::size_t>(end_row - first_row), 0);
  ordered_.assign(static_cast<std::size_t>(channels_), Channel{});
  for (auto& ch : ordered_) ch.start.assign(nt + 1, std::vector<Index>(ns, 0));
  for (int t = 0; t < threads_; ++t)
    for (Index r = row_begin(t); r < row_end(t); ++r)
      for (int c = 0; c < channels_; ++c)
        columns(r, c, [&](Index I) {
          const Index s = slot_[static_cast<std::size_t>(I)];
          if (s < 0 || first_[static_cast<std::size_t>(s)] == t) return;
          seam_row_[static_cast<std::size_t>(r - first_row)] = 1;
          ++ordered_[static_cast<std::size_t>(c)].start[static_cast<std::size_t>(t)][static_cast<std::size_t>(s)];
        });

  const auto ranks = linked_ ? links_.ghosts->size() : 0;
  for (int c = 0; c < channels_; ++c) {
    Channel& ch = ordered_[static_cast<std::size_t>(c)];
    // What the other ranks' rows contribute to this rank's shared particles: each rank
    // tells each owner how many records each of its ghosts gets.
    std::vector<std::vector<Index>> remote(ranks);
    if (linked_) {
      std::vector<std::vector<std::int64_t>> send(ranks), recv;
      for (std::size_t p = 0; p < ranks; ++p)
        for (Index g : (*links_.ghosts)[p]) {
          const auto s = static_cast<std::size_t>(slot_[static_cast<std::size_t>(g)]);
          std::int64_t own = sends_first_sum(g) ? 1 : 0;
          for (std::size_t t = 0; t < nt; ++t) own += ch.start[t][s];
          send[p].push_back(own);
        }
      links_.exchange_counts(send, recv);
      for (std::size_t p = 0; p < ranks; ++p) {
        if ((*links_.holders)[p].size() != recv[p].size())
          throw std::logic_error(fmt::format("ordered scatter: rank {} sent {} record counts for the {} particles "
                                             "it holds of rank {}", p, recv[p].size(), (*links_.holders)[p].size(),
                                             links_.rank));
        remote[p].assign(recv[p].begin(), recv[p].end());
      }
    }
    // Each seam's segment: the records of the lower ranks, this rank's threads in order,
    // then the higher ranks'. `run` walks it.
    std::vector<Index> run(ns, 0);
    ch.segment.assign(ns + 1, 0);
    std::vector<Index> size(ns, 0);
    for (std::size_t s = 0; s < ns; ++s)
      for (std::size_t t = 0; t < nt; ++t) size[s] += ch.start[t][s];
    for (std::size_t p = 0; p < ranks; ++p)
      for (std::size_t j = 0; j < remote[p].size(); ++j)
        size[static_cast<std::size_t>(slot_[static_cast<std::size_t>((*links_.holders)[p][j])])] += remote[p][j];
    for (std::size_t s = 0; s < ns; ++s) ch.segment[s + 1] = ch.segment[s] + size[s];
    for (std::size_t s = 0; s < ns; ++s) run[s] = ch.segment[s];
    ch.recv_at.assign(ranks, {});
    ch.recv_count = remote;
    const auto place_remote = [&](std::size_t p) {
      for (std::size_t j = 0; j < remote[p].size(); ++j) {
        const auto s = static_cast<std::size_t>(slot_[static_cast<std::size_t>((*links_.holders)[p][j])]);
        ch.recv_at[p].push_back(run[s]);
        run[s] += remote[p][j];
      }
    };
    const auto me = static_cast<std::size_t>(links_.rank);
    for (std::size_t p = 0; p < ranks && p < me; ++p) place_remote(p);
    for (std::size_t t = 0; t <= nt; ++t)
      for (std::size_t s = 0; s < ns; ++s) {
        const Index count = t < nt ? ch.start[t][s] : 0;
        ch.start[t][s] = run[s];
        run[s] += count;
      }
    for (std::size_t p = me + 1; p < ranks; ++p) place_remote(p);
    ch.send_at.assign(ranks, {});
    ch.send_count.assign(ranks, {});
    for (std::size_t p = 0; p < ranks; ++p)
      for (Index g : (*links_.ghosts)[p]) {
        const auto s = static_cast<std::size_t>(slot_[static_cast<std::size_t>(g)]);
        ch.send_at[p].push_back(ch.start[0][s]);
        ch.send_count[p].push_back(ch.start[nt][s] - ch.start[0][s]);
      }
    ch.records.assign(static_cast<std::size_t>(ch.segment[ns]), Vec3::Zero());
    ch.cursor.assign(nt, std::vector<Index>(ns, 0));
  }
  allocate_buffers(n);
  send_.assign(ranks, {});
  recv_.assign(ranks, {});
}

// new Vec3[n] leaves the entries uninitialised: a page of a thread's buffer becomes
// resident only when `clear` or the thread's rows touch it, i.e. within its columns
// [col_lo, col_hi). Zero-filled vectors made every thread's buffer resident over the
// whole body (24 B per particle, thread and channel).
void RowScatter::allocate_buffers(Index n_columns) {
  buffers_.clear();
  for (int b = 0; b < threads_ * channels_; ++b) buffers_.emplace_back(static_cast<std::size_t>(n_columns));
}

int RowScatter::team_threads() { return std::max(1, std::min(omp_get_max_threads(), omp_get_thread_limit())); }

void RowScatter::clear(int t) {
  const auto lo = col_lo_[static_cast<std::size_t>(t)], hi = col_hi_[static_cast<std::size_t>(t)];
  for (int c = 0; c < channels_; ++c) std::fill(buffer(t, c) + lo, buffer(t, c) + hi, Vec3::Zero());
  for (auto& ch : ordered_) ch.cursor[static_cast<std::size_t>(t)] = ch.start[static_cast<std::size_t>(t)];
}

RowScatter::Sink RowScatter::sink(int t, int channel, Index row) {
  Sink s;
  s.out_ = buffer(t, channel);
  if (!seam_row_.empty() && seam_row_[static_cast<std::size_t>(row - first_row_)] != 0) {
    Channel& ch = ordered_[static_cast<std::size_t>(channel)];
    s.slot_ = slot_.data();
    s.first_ = first_.data();
    s.thread_ = t;
    s.cursor_ = ch.cursor[static_cast<std::size_t>(t)].data();
    s.records_ = ch.records.data();
  }
  return s;
}

void RowScatter::exchange_records(int channel) {
  Channel& ch = ordered_[static_cast<std::size_t>(channel)];
  const auto ranks = send_.size();
  for (std::size_t p = 0; p < ranks; ++p) {
    send_[p].clear();
    for (std::size_t j = 0; j < ch.send_at[p].size(); ++j) {
      const Index g = (*links_.ghosts)[p][j];
      if (sends_first_sum(g)) {  // this rank's first contributions: the owner's fold starts from their sum
        const int first = first_[static_cast<std::size_t>(slot_[static_cast<std::size_t>(g)])];
        const Vec3& v = buffers_[static_cast<std::size_t>(first * channels_ + channel)][static_cast<std::size_t>(g)];
        send_[p].insert(send_[p].end(), v.data(), v.data() + 3);
      }
      for (Index k = 0; k < ch.send_count[p][j]; ++k) {
        const Vec3& v = ch.records[static_cast<std::size_t>(ch.send_at[p][j] + k)];
        send_[p].insert(send_[p].end(), v.data(), v.data() + 3);
      }
    }
    Index expected = 0;
    for (Index count : ch.recv_count[p]) expected += count;
    recv_[p].assign(3 * static_cast<std::size_t>(expected), 0.0);
  }
  links_.exchange_values(send_, recv_);
  for (std::size_t p = 0; p < ranks; ++p) {
    std::size_t next = 0;
    for (std::size_t j = 0; j < ch.recv_at[p].size(); ++j)
      for (Index k = 0; k < ch.recv_count[p][j]; ++k, next += 3)
        ch.records[static_cast<std::size_t>(ch.recv_at[p][j] + k)] =
            Vec3(recv_[p][next], recv_[p][next + 1], recv_[p][next + 2]);
  }
}

void RowScatter::fold(int channel, double scale, std::vector<Vec3>& out, bool add) {
  if (ordered_.empty() || seams_.empty()) return;
  Channel& ch = ordered_[static_cast<std::size_t>(channel)];
  const auto ns = static_cast<Index>(seams_.size());
  for (std::size_t t = 0; t < ch.cursor.size(); ++t)
    for (std::size_t s = 0; s < seams_.size(); ++s)
      if (ch.cursor[t][s] != ch.start[t + 1][s])
        throw std::logic_error(fmt::format("ordered scatter: thread {} made {} contributions to particle {} in "
                                           "channel {}, its plan {}", t, ch.cursor[t][s] - ch.start[t][s],
                                           seams_[s], channel, ch.start[t + 1][s] - ch.start[t][s]));
  if (linked_) exchange_records(channel);
#pragma omp parallel for schedule(static)
  for (Index s = 0; s < ns; ++s) {
    if (owned_[static_cast<std::size_t>(s)] == 0) continue;
    const auto I = static_cast<std::size_t>(seams_[static_cast<std::size_t>(s)]);
    // The first thread's contributions, added in its buffer in row order, then the
    // later threads' records in order.
    const int first = first_[static_cast<std::size_t>(s)];
    Vec3 sum = first >= 0 ? buffers_[static_cast<std::size_t>(first * channels_ + channel)][I] : Vec3::Zero();
    for (Index k = ch.segment[s]; k < ch.segment[s + 1]; ++k) sum += ch.records[static_cast<std::size_t>(k)];
    auto& o = out[I];
    o = add ? Vec3(o + scale * sum) : Vec3(scale * sum);
  }
}

std::size_t RowScatter::records_sent() const {
  std::size_t n = 0;
  for (const auto& ch : ordered_)
    for (std::size_t p = 0; p < ch.send_count.size(); ++p)
      for (std::size_t j = 0; j < ch.send_count[p].size(); ++j)
        n += static_cast<std::size_t>(ch.send_count[p][j]) + (sends_first_sum((*links_.ghosts)[p][j]) ? 1 : 0);
  return n;
}

// Per particle this rank shares with others: 1 when it is the lowest rank whose rows
// reach it. The holders tell each owner which of its particles their rows reach; the
// owner, which knows every holder, answers each with the lowest.
std::vector<char> RowScatter::lowest_reaching_rank(const std::vector<Index>& reached_by) const {
  const auto ranks = links_.ghosts->size();
  const auto me = static_cast<std::size_t>(links_.rank);
  std::vector<std::vector<std::int64_t>> reach(ranks), heard;
  for (std::size_t p = 0; p < ranks; ++p)
    for (Index g : (*links_.ghosts)[p])
      reach[p].push_back(reached_by[static_cast<std::size_t>(g)] != kUntouched ? 1 : 0);
  links_.exchange_counts(reach, heard);
  for (std::size_t p = 0; p < ranks; ++p)
    if (heard[p].size() != (*links_.holders)[p].size())
      throw std::logic_error(fmt::format("ordered scatter: rank {} said which of {} particles its rows reach, of the "
                                         "{} it holds of rank {}", p, heard[p].size(), (*links_.holders)[p].size(),
                                         links_.rank));
  // For each particle this rank owns and others hold: the lowest rank reaching it.
  std::vector<std::int64_t> lowest_of(reached_by.size(), static_cast<std::int64_t>(ranks));
  for (std::size_t p = 0; p < ranks; ++p)
    for (std::size_t j = 0; j < (*links_.holders)[p].size(); ++j) {
      const auto I = static_cast<std::size_t>((*links_.holders)[p][j]);
      if (reached_by[I] != kUntouched) lowest_of[I] = std::min(lowest_of[I], static_cast<std::int64_t>(me));
      if (heard[p][j] != 0) lowest_of[I] = std::min(lowest_of[I], static_cast<std::int64_t>(p));
    }
  std::vector<std::vector<std::int64_t>> answer(ranks), told;
  for (std::size_t p = 0; p < ranks; ++p)
    for (Index I : (*links_.holders)[p])
      answer[p].push_back(lowest_of[static_cast<std::size_t>(I)] == static_cast<std::int64_t>(p) ? 1 : 0);
  links_.exchange_counts(answer, told);
  std::vector<char> lowest(reached_by.size(), 0);
  for (std::size_t p = 0; p < ranks; ++p) {
    if (told[p].size() != (*links_.ghosts)[p].size())
      throw std::logic_error(fmt::format("ordered scatter: rank {} answered for {} of the {} particles rank {} holds "
                                         "of it", p, told[p].size(), (*links_.ghosts)[p].size(), links_.rank));
    for (std::size_t j = 0; j < told[p].size(); ++j)
      if (told[p][j] != 0) lowest[static_cast<std::size_t>((*links_.ghosts)[p][j])] = 1;
    for (Index I : (*links_.holders)[p])
      if (lowest_of[static_cast<std::size_t>(I)] == static_cast<std::int64_t>(me))
        lowest[static_cast<std::size_t>(I)] = 1;
  }
  return lowest;
}

std::size_t RowScatter::record_count() const {
  std::size_t n = 0;
  for (const auto& ch : ordered_) n += ch.records.size();
  return n;
}

Vec3 RowScatter::thread_sum(int channel, Index I) const {
  Vec3 sum = Vec3::Zero();
  for (int s = 0; s < threads_; ++s)
    if (I >= col_lo_[static_cast<std::size_t>(s)] && I < col_hi_[static_cast<std::size_t>(s)])
      sum += buffers_[static_cast<std::size_t>(s * channels_ + channel)][static_cast<std::size_t>(I)];
  return sum;
}

std::pair<Index, Index> RowScatter::reduce_block(int t) const {
  // Thread t's static block of columns, within the columns any block touches (adding
  // zero elsewhere changes nothing; a term's few rows then cost no pass over the body).
  auto [begin, end] = static_block(n_columns_, t, threads_);
  Index lo = n_columns_, hi = 0;
  for (std::size_t s = 0; s < col_lo_.size(); ++s) {
    lo = std::min(lo, col_lo_[s]);
    hi = std::max(hi, col_hi_[s]);
  }
  return {std::max(begin, lo), std::min(end, hi)};
}

void RowScatter::reduce(int t, int channel, double scale, std::vector<Vec3>& out) const {
  const auto [begin, end] = static_block(n_columns_, t, threads_);
  for (Index I = begin; I < end; ++I)
    if (!seam(I)) out[static_cast<std::size_t>(I)] = scale * thread_sum(channel, I);
}

void RowScatter::reduce_add(int t, int channel, double scale, std::vector<Vec3>& out) const {
  const auto [begin, end] = reduce_block(t);
  for (Index I = begin; I < end; ++I)
    if (!seam(I)) out[static_cast<std::size_t>(I)] += scale * thread_sum(channel, I);
}

std::size_t RowScatter::bytes() const {
  std::size_t b = (row_begin_.size() + col_lo_.size() + col_hi_.size() + slot_.size() + seams_.size()) * sizeof(Index);
  for (std::size_t t = 0; t < col_lo_.size(); ++t)  // the resident part (allocate_buffers)
    b += static_cast<std::size_t>(channels_) * static_cast<std::size_t>(col_hi_[t] - col_lo_[t]) * sizeof(Vec3);
  b += seam_row_.size() + owned_.size() + first_.size() * sizeof(int);
  for (const auto& ch : ordered_) {
    b += ch.records.size() * sizeof(Vec3) + ch.segment.size() * sizeof(Index);
    for (const auto* table : {&ch.start, &ch.cursor, &ch.send_at, &ch.send_count, &ch.recv_at, &ch.recv_count})
      for (const auto& v : *table) b += v.size() * sizeof(Index);
  }
  return b;
}

}  // namespace rkpm::rk
