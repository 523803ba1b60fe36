// Node numbering and hexahedra of a structured (i, j, k) grid, shared by the
// block and sphere generators.
#pragma once

#include "rkpm/particles/cloud.hpp"

#include <array>
#include <cstdint>
#include <limits>
#include <string>

namespace rkpm::particles::detail {

// Throws CloudError unless `count` particles (or elements) of the generator `what` can
// be indexed by the 32-bit ids of a cloud; the products are formed in 64 bits first.
inline void check_index_range(std::int64_t count, const std::string& what) {
  if (count > std::numeric_limits<std::int32_t>::max())
    throw CloudError(what + ": " + std::to_string(count) + " particles or cells, more than the " +
                     std::to_string(std::numeric_limits<std::int32_t>::max()) + " a 32-bit index can address");
}

struct StructuredGrid {
  std::array<int, 3> cells;

  // Throws CloudError (naming `what`) when the grid's nodes cannot be indexed.
  void check(const std::string& what) const {
    std::int64_t nodes = 1;
    for (int axis = 0; axis < 3; ++axis) {
      nodes *= std::int64_t{cells[axis]} + 1;
      check_index_range(nodes, what);
    }
  }

  int nodes_along(int axis) const { return cells[axis] + 1; }
  int n_nodes() const { return nodes_along(0) * nodes_along(1) * nodes_along(2); }
  std::int32_t node(int i, int j, int k) const {
    return static_cast<std::int32_t>(i + nodes_along(0) * (j + nodes_along(1) * k));
  }
  bool on_boundary(int i, int j, int k) const {
    return i == 0 || j == 0 || k == 0 || i == cells[0] || j == cells[1] || k == cells[2];
  }

  // Hexahedra in VTK order; positive volume when the grid maps right-handedly.
  void add_hexahedra(Mesh& mesh) const {
    for (int k = 0; k < cells[2]; ++k) {
      for (int j = 0; j < cells[1]; ++j) {
        for (int i = 0; i < cells[0]; ++i) {
          const std::int32_t ids[8] = {node(i, j, k),         node(i + 1, j, k),
                                       node(i + 1, j + 1, k), node(i, j + 1, k),
                                       node(i, j, k + 1),     node(i + 1, j, k + 1),
                                       node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)};
          mesh.add_element(ElementType::Hex8, ids);
        }
      }
    }
  }
};

}  // namespace rkpm::particles::detail
