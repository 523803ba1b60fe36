// A tetrahedral cloud for the tests: every hexahedron of a block split into six
// tetrahedra around its 0-6 diagonal (Kuhn), which is conforming across cells.
#pragma once

#include "rkpm/particles/generators.hpp"

#include <Eigen/Geometry>

#include <utility>

namespace rkpm::particles::testing {

inline Cloud tet_block(const BlockSpec& spec) {
  const Cloud hexes = make_block(spec);
  Cloud tets;
  tets.name = "tet block";
  tets.X = hexes.X;
  static const int kuhn[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                                 {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  for (int e = 0; e < hexes.mesh.n_elements(); ++e) {
    const std::int32_t* h = hexes.mesh.element_nodes(e);
    for (const auto& t : kuhn) {
      std::int32_t ids[4] = {h[t[0]], h[t[1]], h[t[2]], h[t[3]]};
      const Vec3& x0 = tets.X[ids[0]];
      if ((tets.X[ids[1]] - x0).cross(tets.X[ids[2]] - x0).dot(tets.X[ids[3]] - x0) < 0) std::swap(ids[1], ids[2]);
      tets.mesh.add_element(ElementType::Tet4, ids);
    }
  }
  finalize_cloud(tets);
  return tets;
}

}  // namespace rkpm::particles::testing
