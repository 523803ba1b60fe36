#include "rkpm/par/ghost_exchange.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace rkpm::par {

namespace {
void pack(const std::vector<Index>& ids, const double* data, int stride, std::vector<double>& out) {
  const auto k = static_cast<std::size_t>(stride);
  out.resize(k * ids.size());
  for (std::size_t j = 0; j < ids.size(); ++j)
    std::copy_n(data + k * static_cast<std::size_t>(ids[j]), k, out.data() + k * j);
}
}  // namespace

void GhostExchange::build(const Comm& comm, const std::vector<Index>& offset,
                          const std::vector<rk::RowScatter::Pattern>& patterns, std::vector<Index> extra) {
  if (offset.size() != static_cast<std::size_t>(comm.size()) + 1)
    throw std::invalid_argument(fmt::format("ghost layer: {} particle ranges for {} ranks", offset.size() - 1,
                                            comm.size()));
  const Index begin = offset[static_cast<std::size_t>(comm.rank())];
  const Index end = offset[static_cast<std::size_t>(comm.rank()) + 1];
  std::vector<Index> columns = std::move(extra);
  for (const auto& p : patterns)
    for (Index L = begin; L < end; ++L)
      for (Index k = (*p.row_offset)[L]; k < (*p.row_offset)[L + 1]; ++k) columns.push_back((*p.col)[k]);
  build(comm, offset, std::move(columns));
}

void GhostExchange::build(const Comm& comm, const std::vector<Index>& offset, std::vector<Index> ghosts) {
  comm_ = &comm;
  const auto ranks = static_cast<std::size_t>(comm.size());
  if (offset.size() != ranks + 1)
    throw std::invalid_argument(fmt::format("ghost layer: {} particle ranges for {} ranks", offset.size() - 1, ranks));
  offset_ = offset;
  begin_ = offset[static_cast<std::size_t>(comm.rank())];
  end_ = offset[static_cast<std::size_t>(comm.rank()) + 1];
  const Index n = offset.back();
  for (Index I : ghosts)
    if (I < 0 || I >= n)
      throw std::logic_error(fmt::format("ghost layer: particle {} is outside the body's {} particles", I, n));
  ghosts.erase(std::remove_if(ghosts.begin(), ghosts.end(), [&](Index I) { return I >= begin_ && I < end_; }),
               ghosts.end());
  std::sort(ghosts.begin(), ghosts.end());
  ghosts.erase(std::unique(ghosts.begin(), ghosts.end()), ghosts.end());

  // Sorted ids split by owner: the ranges are in rank order.
  ghosts_.assign(ranks, {});
  for (Index g : ghosts) {
    const auto owner = static_cast<std::size_t>(std::upper_bound(offset.begin(), offset.end(), g) - offset.begin()) - 1;
    ghosts_[owner].push_back(g);
  }
  // Tell each owner which of its particles this rank holds.
  std::vector<std::vector<std::int64_t>> ask(ranks), told;
  for (std::size_t r = 0; r < ranks; ++r) ask[r].assign(ghosts_[r].begin(), ghosts_[r].end());
  comm.exchange(ask, told);
  holders_.assign(ranks, {});
  for (std::size_t r = 0; r < ranks; ++r) {
    if (r == static_cast<std::size_t>(comm.rank())) continue;
    for (std::int64_t id : told[r]) {
      if (id < begin_ || id >= end_)
        throw std::logic_error(fmt::format("ghost layer: rank {} asks rank {} for particle {}, which it does not "
                                           "own (it owns {} to {})", r, comm.rank(), id, begin_, end_ - 1));
      holders_[r].push_back(static_cast<Index>(id));
    }
  }
  send_.assign(ranks, {});
  recv_.assign(ranks, {});
}

void GhostExchange::pull(double* data, int stride) const {
  if (!comm_->parallel()) return;
  const auto k = static_cast<std::size_t>(stride);
  const auto ranks = holders_.size();
  for (std::size_t r = 0; r < ranks; ++r) {
    pack(holders_[r], data, stride, send_[r]);
    recv_[r].resize(k * ghosts_[r].size());
  }
  comm_->exchange_known(send_, recv_);
  for (std::size_t r = 0; r < ranks; ++r)
    for (std::size_t j = 0; j < ghosts_[r].size(); ++j)
      std::copy_n(recv_[r].data() + k * j, k, data + k * static_cast<std::size_t>(ghosts_[r][j]));
}

void GhostExchange::push_add(double* data, int stride) const {
  if (!comm_->parallel()) return;
  const auto k = static_cast<std::size_t>(stride);
  const auto ranks = holders_.size();
  for (std::size_t r = 0; r < ranks; ++r) {
    pack(ghosts_[r], data, stride, send_[r]);
    recv_[r].resize(k * holders_[r].size());
  }
  comm_->exchange_known(send_, recv_);
  for (std::size_t r = 0; r < ranks; ++r)  // rank order: the same sum on every run
    for (std::size_t j = 0; j < holders_[r].size(); ++j) {
      double* out = data + k * static_cast<std::size_t>(holders_[r][j]);
      for (std::size_t c = 0; c < k; ++c) out[c] += recv_[r][k * j + c];
    }
}

rk::RowScatter::Links GhostExchange::scatter_links() const {
  rk::RowScatter::Links links;
  links.rank = comm_->rank();
  links.owned_begin = begin_;
  links.owned_end = end_;
  links.ghosts = &ghosts_;
  links.holders = &holders_;
  const Comm* comm = comm_;
  links.exchange_counts = [comm](const std::vector<std::vector<std::int64_t>>& send,
                                 std::vector<std::vector<std::int64_t>>& recv) { comm->exchange(send, recv); };
  links.exchange_values = [comm](const std::vector<std::vector<double>>& send, std::vector<std::vector<double>>& recv) {
    comm->exchange_known(send, recv);
  };
  return links;
}

std::size_t GhostExchange::ghost_count() const {
  std::size_t n = 0;
  for (const auto& g : ghosts_) n += g.size();
  return n;
}

std::size_t GhostExchange::send_count() const {
  std::size_t n = 0;
  for (const auto& h : holders_) n += h.size();
  return n;
}

}  // namespace rkpm::par
