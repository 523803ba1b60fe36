// Partition of a body's particles over the ranks of a run, made once on the
// reference configuration.
//
// Why METIS over the mesh's edge graph: the operators of total-Lagrangian RKPM are
// fixed, and each step a rank exchanges the displacements of the particles its rows
// reference but do not own (ghosts). The kernel supports span a few mesh edges
// around each particle, so a partition that cuts few mesh edges has few ghosts. METIS
// k-way minimises exactly that cut, with balanced parts, from a graph that exists
// before the operators are built; coordinate bisection would ignore a thin shell's
// through-thickness connectivity and cut across its wall. METIS is deterministic for
// a fixed seed, so the same cloud and rank count always give the same partition.
//
// The particles are then renumbered so that each part is one contiguous range (in
// the cloud's previous order within the part): a rank owns particles [offset[r],
// offset[r+1]) of every body, and every loop over owned particles is a plain range.
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

// Parts of the cloud's mesh-edge graph, balanced in particle count. One part is the
// identity. Throws std::invalid_argument for more parts than particles.
Partition partition_cloud(const particles::Cloud& cloud, int parts);

// Edges of the mesh cut by the partition (after renumbering: ranges `offset`), a
// measure of its quality for the partition study.
std::int64_t cut_edges(const particles::Cloud& cloud, const std::vector<Index>& offset);

}  // namespace rkpm::par
