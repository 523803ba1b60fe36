#include "rkpm/particles/cloud.hpp"

#include <algorithm>

namespace rkpm::particles {

int nodes_per_element(ElementType type) {
  switch (type) {
    case ElementType::Tet4: return 4;
    case ElementType::Hex8: return 8;
  }
  throw CloudError("unknown element type " + std::to_string(static_cast<int>(type)));
}

void Mesh::add_element(ElementType t, const std::int32_t* ids) {
  if (offset.empty()) offset.push_back(0);
  type.push_back(t);
  nodes.insert(nodes.end(), ids, ids + nodes_per_element(t));
  offset.push_back(static_cast<std::int32_t>(nodes.size()));
}

std::uint32_t Cloud::surface_bit(const std::string& surface) const {
  const auto it = std::find(surface_names.begin(), surface_names.end(), surface);
  if (it == surface_names.end()) return 0;
  return std::uint32_t{1} << (it - surface_names.begin());
}

bool Cloud::on_surface(std::int32_t particle, const std::string& surface) const {
  return (surface_mask.at(particle) & surface_bit(surface)) != 0;
}

}  // namespace rkpm::particles
