#include "rkpm/particles/renumber.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace rkpm::particles {

namespace {
// The 21 low bits of v spread to every third bit (bit i -> bit 3 i).
std::uint64_t spread_bits(std::uint64_t v) {
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffULL;
  v = (v | v << 16) & 0x1f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}
}  // namespace

std::vector<std::int32_t> morton_order(const std::vector<Vec3>& X) {
  std::vector<std::int32_t> order(X.size());
  if (X.empty()) return order;
  Vec3 lo = X.front(), hi = X.front();
  for (const auto& x : X) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  const double steps = static_cast<double>((1u << 21) - 1);
  const double extent = std::max((hi - lo).maxCoeff(), 1e-300);  // cubic steps (renumber.hpp)
  std::vector<std::pair<std::uint64_t, std::int32_t>> keyed(X.size());
  for (std::size_t i = 0; i < X.size(); ++i) {
    std::uint64_t key = 0;
    for (int d = 0; d < 3; ++d) {
      const double t = std::clamp((X[i][d] - lo[d]) / extent, 0.0, 1.0);
      key |= spread_bits(static_cast<std::uint64_t>(std::floor(t * steps))) << d;
    }
    keyed[i] = {key, static_cast<std::int32_t>(i)};
  }
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t k = 0; k < keyed.size(); ++k) order[k] = keyed[k].second;
  return order;
}

void renumber(Cloud& cloud, const std::vector<std::int32_t>& order) {
  const std::size_t n = cloud.size();
  if (order.size() != n) throw std::invalid_argument("renumber: the order must list every particle once");
  std::vector<std::int32_t> new_id(n, -1);
  for (std::size_t k = 0; k < n; ++k) {
    const auto old = order[k];
    if (old < 0 || static_cast<std::size_t>(old) >= n || new_id[static_cast<std::size_t>(old)] != -1)
      throw std::invalid_argument("renumber: the order must list every particle once");
    new_id[static_cast<std::size_t>(old)] = static_cast<std::int32_t>(k);
  }
  std::vector<Vec3> X(n);
  std::vector<std::uint32_t> mask(cloud.surface_mask.empty() ? 0 : n);
  for (std::size_t k = 0; k < n; ++k) {
    X[k] = cloud.X[static_cast<std::size_t>(order[k])];
    if (!mask.empty()) mask[k] = cloud.surface_mask[static_cast<std::size_t>(order[k])];
  }
  cloud.X = std::move(X);
  cloud.surface_mask = std::move(mask);
  for (auto& node : cloud.mesh.nodes) node = new_id[static_cast<std::size_t>(node)];
  // Derived again from the renumbered mesh.
  cloud.volume.clear();
  cloud.boundary_faces.clear();
  cloud.boundary_particles.clear();
  cloud.boundary_normal.clear();
  cloud.boundary_area.clear();
  cloud.boundary_index.clear();
  finalize_cloud(cloud);
}

}  // namespace rkpm::particles
