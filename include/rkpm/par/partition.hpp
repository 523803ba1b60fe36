// Partition of a body's particles over the ranks of a run, made once on the
// reference configuration. A rank owns one contiguous range [offset[r], offset[r+1])
// of every body, so every loop over owned particles is a plain range.
//
// Two methods:
// - `kCurve` (what runs use): the cloud's own order cut into equal ranges. The cloud is
//   numbered along a Morton curve (rk.particle_order, particles/renumber.hpp), so each
//   range is a compact piece of the body, and the particles keep their one-process
//   numbers. That is what makes a run on any rank count compute the same bits as one
//   process: every rank builds each row of the operators from the same neighbours in
//   the same order, and the sums over particles follow the one-process numbering
//   (rk/row_scatter.hpp, common/exact_sum.hpp). On a block, the first cut of a Morton
//   order is a plane through the middle, the best cut there is.
// - `kMetis`: METIS k-way over the mesh's edge graph, which minimises the cut edges
//   (the ghosts) on any shape, then renumbered so that each part is contiguous. It
//   cuts a shell or a sphere into parts with somewhat fewer ghosts, but the renumbering
//   changes every summation order, so its runs match one process only to round-off
//   carried along the run (docs/theory/distributed.md). Kept for the partition study.
#pragma once

#include "rkpm/common/types.hpp"
#include "rkpm/particles/cloud.hpp"

#include <cstdint>
#include <vector>

namespace rkpm::par {

struct Partition {
  std::vector<std::int32_t> order;  // order[k] = the particle that becomes particle k (particles::renumber)
  std::vector<Index> offset;        // parts + 1: part r holds the new ids [offset[r], offset[r+1])
};

enum class PartitionMethod { kCurve, kMetis };

// Parts balanced in particle count (kCurve: sizes differ by at most one). One part is
// the identity. Throws std::invalid_argument for more parts than particles.
Partition partition_cloud(const particles::Cloud& cloud, int parts,
                          PartitionMethod method = PartitionMethod::kCurve);

// Edges of the mesh cut by the partition (after renumbering: ranges `offset`), a
// measure of its quality for the partition study.
std::int64_t cut_edges(const particles::Cloud& cloud, const std::vector<Index>& offset);

}  // namespace rkpm::par
