// Edges of the linear elements in VTK node ordering.
#pragma once

#include "rkpm/particles/cloud.hpp"

#include <array>
#include <vector>

namespace rkpm::rk {

inline const std::vector<std::array<int, 2>>& element_edges(particles::ElementType type) {
  static const std::vector<std::array<int, 2>> tet = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  static const std::vector<std::array<int, 2>> hex = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                                      {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  return type == particles::ElementType::Tet4 ? tet : hex;
}

}  // namespace rkpm::rk
