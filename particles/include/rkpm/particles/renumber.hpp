// Particle renumbering along a space-filling curve.
//
// The generators number particles layer by layer (a shell: one whole layer after the
// other), so the particles of one kernel support are spread over the whole id range and
// every row of the operators gathers from far-apart memory. Ordered along a Morton
// (Z-order) curve, particles near in space are near in id: each row's columns sit close
// together, and consecutive rows reuse what the previous ones brought into cache.
#pragma once

#include "rkpm/particles/cloud.hpp"

#include <cstdint>
#include <vector>

namespace rkpm::particles {

// order[k] = the current id of the particle that becomes particle k: the particles
// sorted by the Morton key of their position quantised to 2^21 steps of the bounding
// box's longest side on every axis (ties, which only coincident positions give, by id).
// Deterministic. The steps are cubes, not a stretch of the box: the curve's first
// halving then cuts the longest side, so the ranges a distributed run gives each rank
// (par/partition.hpp) and each thread are compact pieces, not slabs along a long side.
std::vector<std::int32_t> morton_order(const std::vector<Vec3>& X);

// Renumbers the cloud: particle k becomes the old particle order[k]. Positions and
// surface masks move with their particles, the mesh's connectivity is rewritten, and
// everything finalize_cloud derives (volumes, boundary faces and particles) is derived
// again for the new numbering. `order` must be a permutation of 0 .. size-1.
void renumber(Cloud& cloud, const std::vector<std::int32_t>& order);

}  // namespace rkpm::particles
