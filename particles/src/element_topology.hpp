// Local connectivity of the linear elements in VTK node ordering: outward faces,
// edges with the two faces that meet there, and the corner frames used to detect
// inverted elements. Internal to the particle library.
#pragma once

#include "rkpm/particles/cloud.hpp"

#include <array>
#include <vector>

namespace rkpm::particles::detail {

struct LocalFace {
  int n_nodes = 0;
  std::array<int, 4> nodes{};  // right-hand rule gives the outward normal
};

// Edge (first, second) with first < second. The median-dual facet of the edge,
// [mid, centroid(face_a), centroid(element), centroid(face_b)], has its normal
// pointing from `first` towards `second` on every non-inverted element.
struct LocalEdge {
  int first = 0;
  int second = 0;
  int face_a = 0;
  int face_b = 0;
};

struct ElementTopology {
  ElementType type{};
  int n_nodes = 0;
  std::vector<LocalFace> faces;
  std::vector<LocalEdge> edges;
  std::vector<std::vector<int>> edges_of_node;      // local node -> indices into edges
  std::vector<std::array<int, 3>> corner_neighbors;  // local node -> 3 edge neighbours, right-handed
};

// Built once from the reference element, so the orientation conventions are
// derived rather than typed in by hand.
const ElementTopology& topology(ElementType type);

}  // namespace rkpm::particles::detail
