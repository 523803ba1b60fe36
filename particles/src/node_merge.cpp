#include "node_merge.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace rkpm::particles::detail {

MergedNodes merge_coincident_nodes(const std::vector<Vec3>& points, double quantum) {
  const std::size_t n = points.size();
  std::vector<std::array<std::int64_t, 3>> key(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) key[i][k] = std::llround(points[i][k] / quantum);
  }
  // Sort by key, ties by index: the first copy of each node leads its group.
  std::vector<std::int32_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) {
    return key[a] != key[b] ? key[a] < key[b] : a < b;
  });
  std::vector<std::int32_t> leader(n);
  for (std::size_t i = 0; i < n; ++i) {
    const bool starts_group = i == 0 || key[order[i]] != key[order[i - 1]];
    leader[order[i]] = starts_group ? order[i] : leader[order[i - 1]];
  }
  MergedNodes merged;
  merged.id.assign(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    if (leader[i] == static_cast<std::int32_t>(i)) {
      merged.id[i] = static_cast<std::int32_t>(merged.points.size());
      merged.points.push_back(points[i]);
    } else {
      merged.id[i] = merged.id[leader[i]];
    }
  }
  return merged;
}

}  // namespace rkpm::particles::detail
