// Candidate particle pairs between two bodies for a short-range interaction
// (a Verlet list with a skin).
//
// At a build, a nanoflann kd-tree over body B's current positions is queried with
// radius cutoff + skin around every particle of body A. The list is kept while no
// particle of either body has moved more than skin/2 since that build: two particles
// now within the cutoff were then within cutoff + 2 (skin/2), so no pair is missed.
// The force loop filters the list by the cutoff.
//
// Storage is compressed rows: row I (a particle of A) lists its partners J in B in
// increasing id; the transpose lists, for each J, the pair entries that reference it,
// ordered by I. Sums over either index therefore run in a fixed order (deterministic,
// no atomics), whatever the tree's layout or the number of threads.
#pragma once

#include "rkpm/common/types.hpp"

#include <cstddef>
#include <functional>
#include <vector>

namespace rkpm::sim {

class ContactPairs {
 public:
  // Which pairs a term can ever use, decided from what does not move (its reference
  // configuration): a pair it rejects is never stored. Empty: every pair is kept.
  using Keep = std::function<bool(Index i, Index j)>;
  // `transpose`: also build the column view (column_offset, column_entry, entry_row),
  // for a term that sums over partners of B; a term that reads the rows only saves it.
  ContactPairs(double cutoff, double skin, Keep keep = {}, bool transpose = true);

  // Rebuilds the list if it was never built, if a body's size changed, or if some
  // particle of A or B moved more than skin/2 since the last build. Returns true
  // when it rebuilt.
  bool update(const std::vector<Vec3>& xa, const std::vector<Vec3>& xb);
  // Unconditional rebuild at the given positions.
  void rebuild(const std::vector<Vec3>& xa, const std::vector<Vec3>& xb);
  // Rebuild for the rows [row_begin, row_end) of A against the listed particles of B
  // (`columns`, increasing): what one rank of a distributed run holds. The other rows
  // and columns stay empty; the positions of unlisted particles are not read.
  void rebuild(const std::vector<Vec3>& xa, Index row_begin, Index row_end, const std::vector<Vec3>& xb,
               const std::vector<Index>& columns);
  // The largest distance a particle of A in [a_begin, a_end) or of B in [b_begin, b_end)
  // moved since the last build (infinite before the first): the list is stale once it
  // exceeds skin / 2, a test a distributed run makes over every rank.
  double largest_move(const std::vector<Vec3>& xa, Index a_begin, Index a_end, const std::vector<Vec3>& xb,
                      Index b_begin, Index b_end) const;

  double cutoff() const { return cutoff_; }
  double skin() const { return skin_; }
  std::size_t builds() const { return builds_; }
  std::size_t size() const { return partner_.size(); }

  // Pairs of row I (particle I of A): entries row_offset[I] .. row_offset[I+1]-1.
  const std::vector<Index>& row_offset() const { return row_offset_; }
  const std::vector<Index>& partner() const { return partner_; }  // J in B of each entry
  // For particle J of B: entries column_entry[column_offset[J] .. column_offset[J+1]-1]
  // (these three are empty for a list built without its transpose).
  const std::vector<Index>& column_offset() const { return column_offset_; }
  const std::vector<Index>& column_entry() const { return column_entry_; }
  const std::vector<Index>& entry_row() const { return entry_row_; }  // I of each entry

 private:
  static double largest_move(const std::vector<Vec3>& x, const std::vector<Vec3>& at_build, Index begin, Index end);

  double cutoff_, skin_;
  Keep keep_;
  bool transpose_;
  std::size_t builds_ = 0;
  std::vector<Vec3> xa_built_, xb_built_;  // positions at the last build
  std::vector<Index> row_offset_, partner_, entry_row_;
  std::vector<Index> column_offset_, column_entry_;
};

}  // namespace rkpm::sim
