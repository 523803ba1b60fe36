// The fixed ghost layer of one body on one rank, and its two exchanges per step.
//
// Total Lagrangian: the operators are built once on the reference configuration, so
// the particles a rank's rows reference never change. The ghosts are those outside
// the rank's own range; their lists are agreed with the owners once, at set-up (one
// exchange of ids), as CabanaPD does for peridynamics. Each step then
//   pull:     owners send the ghosts' current values (displacements, a material's coupled field);
//   push_add: the ranks send the force contributions their rows made to ghosts back to
//             the owners, which add them in rank order (deterministic for a given rank
//             count).
// A ghost whose owner does not list it cannot happen by construction: the owner learns
// every list from its holders. The lists are checked against the ranges at set-up
// (an id outside every range is an error naming it).
#pragma once

#include "rkpm/common/types.hpp"
#include "rkpm/par/comm.hpp"
#include "rkpm/rk/row_scatter.hpp"

#include <cstddef>
#include <vector>

namespace rkpm::par {

static_assert(sizeof(Vec3) == 3 * sizeof(double), "a std::vector<Vec3> is read as 3 doubles per particle");

class GhostExchange {
 public:
  // `offset` (ranks + 1 entries) gives each rank's range of particles and rows; the
  // patterns are CSR row_offset/col pairs over the body's rows (one row per particle):
  // the ghosts are the columns of the rows this rank owns that it does not own.
  // `extra`: other particles the rank reads (the nodes of the surface faces at its
  // particles, which the current normals need).
  void build(const Comm& comm, const std::vector<Index>& offset,
             const std::vector<rk::RowScatter::Pattern>& patterns, std::vector<Index> extra = {});
  // The same for a given set of particles (any order, repeats and owned ones ignored).
  void build(const Comm& comm, const std::vector<Index>& offset, std::vector<Index> ghosts);

  // field[g] = its owner's field[g], for every ghost g of this rank.
  void pull(std::vector<Vec3>& field) const { pull(field.front().data(), 3); }
  // For every particle I this rank owns: field[I] += the other ranks' field[I], added
  // in rank order.
  void push_add(std::vector<Vec3>& field) const { push_add(field.front().data(), 3); }
  // The same for `stride` doubles per particle, particle i at data[stride * i].
  void pull(double* data, int stride) const;
  void push_add(double* data, int stride) const;

  // This rank's ghosts, grouped by owner rank, each group sorted.
  const std::vector<std::vector<Index>>& ghosts_by_owner() const { return ghosts_; }
  // This rank's particles that other ranks hold, grouped by holder rank, each sorted.
  const std::vector<std::vector<Index>>& holders_by_rank() const { return holders_; }
  // What an ordered scatter needs to fold the ranks' contributions in the one-process
  // order (rk/row_scatter.hpp). The layer must outlive the scatter's plan.
  rk::RowScatter::Links scatter_links() const;
  // Every rank's range: rank r owns [offset()[r], offset()[r+1]).
  const std::vector<Index>& offset() const { return offset_; }
  Index begin() const { return begin_; }
  Index end() const { return end_; }
  std::size_t ghost_count() const;
  // Values this rank sends in one pull (the same count comes back in a push).
  std::size_t send_count() const;
  bool built() const { return comm_ != nullptr; }

 private:
  const Comm* comm_ = nullptr;
  Index begin_ = 0, end_ = 0;
  std::vector<Index> offset_;
  std::vector<std::vector<Index>> ghosts_;    // per rank: its particles this rank holds as ghosts, sorted
  std::vector<std::vector<Index>> holders_;   // per rank: this rank's particles it holds as ghosts, sorted
  mutable std::vector<std::vector<double>> send_, recv_;  // message buffers, sized at build
};

}  // namespace rkpm::par
