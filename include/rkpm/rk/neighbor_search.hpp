// Fixed-radius neighbour queries over a set of points, through a nanoflann kd-tree.
//
// Contract (nanoflann 1.4): radius queries take the SQUARED radius and we ask for
// unsorted results; `query` then sorts by particle id so that every sum over a
// neighbourhood runs in the same order whatever the tree's layout: results are
// deterministic and rows of the flat (CSR) operators come out sorted.
// The tree keeps a reference to `points`: they must outlive it and not move.
// Queries are const and thread-safe; building is not.
#pragma once

#include "rkpm/common/types.hpp"

#include <memory>
#include <utility>
#include <vector>

namespace rkpm::rk {

class NeighborSearch {
 public:
  explicit NeighborSearch(const std::vector<Vec3>& points, int leaf_size = 24);
  ~NeighborSearch();
  NeighborSearch(const NeighborSearch&) = delete;
  NeighborSearch& operator=(const NeighborSearch&) = delete;

  // Ids of all points with |p - x| < radius, sorted by id, with squared distances.
  // `scratch` is reused between calls to avoid allocation.
  void query(const Vec3& x, double radius, std::vector<std::pair<Index, double>>& result) const;
  // The same points, in an order that depends on the tree's layout: for a caller that
  // filters the result and then sorts what is left by id (sorting thousands of
  // candidates of which a few dozen survive cost more than the query).
  void query_unordered(const Vec3& x, double radius, std::vector<std::pair<Index, double>>& result) const;

  // The nearest point to x and its squared distance; among points at exactly that
  // distance, the lowest id (so the answer does not depend on the tree's layout).
  // `scratch` is reused between calls. Requires at least one point.
  std::pair<Index, double> nearest(const Vec3& x, std::vector<std::pair<Index, double>>& scratch) const;

  const std::vector<Vec3>& points() const { return points_; }

 private:
  struct Tree;
  const std::vector<Vec3>& points_;
  std::unique_ptr<Tree> tree_;
};

}  // namespace rkpm::rk
