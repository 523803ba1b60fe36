// Deterministic merge of coincident nodes (the seams of patched meshes).
#pragma once

#include "rkpm/particles/cloud.hpp"

#include <vector>

namespace rkpm::particles::detail {

struct MergedNodes {
  std::vector<Vec3> points;        // one per distinct node, in order of first appearance
  std::vector<std::int32_t> id;    // input index -> index into `points`
};

// Points whose coordinates round to the same multiple of `quantum` are one node.
// Meant for copies that agree to far better than `quantum` (ideally bit for bit):
// two copies straddling a rounding boundary would stay apart.
MergedNodes merge_coincident_nodes(const std::vector<Vec3>& points, double quantum);

}  // namespace rkpm::particles::detail
