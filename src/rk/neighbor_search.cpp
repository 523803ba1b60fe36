#include "rkpm/rk/neighbor_search.hpp"

#include <nanoflann.hpp>

#include <algorithm>
#include <cmath>

namespace rkpm::rk {

namespace {
// nanoflann's dataset adaptor over our own storage: no copy of the points.
struct PointsAdaptor {
  const std::vector<Vec3>& pts;
  std::size_t kdtree_get_point_count() const { return pts.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const { return pts[i][static_cast<int>(dim)]; }
  template <class BBox>
  bool kdtree_get_bbox(BBox&) const { return false; }
};
using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointsAdaptor>,
                                                   PointsAdaptor, 3, Index>;

void sort_by_id(std::vector<std::pair<Index, double>>& result) {
  std::sort(result.begin(), result.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
}
}  // namespace

struct NeighborSearch::Tree {
  PointsAdaptor adaptor;
  KdTree index;
  Tree(const std::vector<Vec3>& pts, int leaf)
      : adaptor{pts}, index(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(static_cast<std::size_t>(leaf))) {
    index.buildIndex();
  }
};

NeighborSearch::NeighborSearch(const std::vector<Vec3>& points, int leaf_size)
    : points_(points), tree_(std::make_unique<Tree>(points, leaf_size)) {}

NeighborSearch::~NeighborSearch() = default;

void NeighborSearch::query_unordered(const Vec3& x, double radius,
                                     std::vector<std::pair<Index, double>>& result) const {
  result.clear();
  if (points_.empty()) return;
  nanoflann::SearchParams params;
  params.sorted = false;
  tree_->index.radiusSearch(x.data(), radius * radius, result, params);  // squared radius
}

void NeighborSearch::query(const Vec3& x, double radius, std::vector<std::pair<Index, double>>& result) const {
  query_unordered(x, radius, result);
  sort_by_id(result);
}

std::pair<Index, double> NeighborSearch::nearest(const Vec3& x,
                                                 std::vector<std::pair<Index, double>>& scratch) const {
  Index id = 0;
  double d2 = 0.0;
  tree_->index.knnSearch(x.data(), 1, &id, &d2);
  // Collect every point at that distance (exact ties) and keep the lowest id. The radius
  // query is strict (< r^2), hence the margin; a zero distance needs a positive radius.
  query(x, std::max(std::sqrt(d2) * (1.0 + 1e-9), 1e-150), scratch);
  std::pair<Index, double> best{id, d2};
  for (const auto& f : scratch)
    if (f.second < best.second || (f.second == best.second && f.first < best.first)) best = f;
  return best;
}

}  // namespace rkpm::rk
