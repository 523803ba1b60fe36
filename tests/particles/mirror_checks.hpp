// Mirror symmetry of a particle cloud: a reflection x_a -> 2 c_a - x_a about a
// plane through `centre` must map the cloud onto itself, particle for particle, and
// with it every quantity the simulator derives from the mesh. A cloud that fails
// carries a preferred direction into every run on it (a sphere resting on a
// uniform block would drift).
#pragma once

#include "rkpm/particles/cloud.hpp"
#include "rkpm/particles/dual_cells.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace rkpm::particles::testing {

inline Vec3 reflect(const Vec3& x, const Vec3& centre, int axis) {
  Vec3 y = x;
  y[axis] = 2.0 * centre[axis] - x[axis];
  return y;
}

// Largest deviation of each mirrored quantity, relative to its natural scale.
struct MirrorErrors {
  int unmatched = 0;          // particles whose mirror image is no particle
  double position = 0.0;      // |X_j - M X_i| / cloud size
  double volume = 0.0;        // |V_j - V_i| / V_i
  int boundary_mismatch = 0;  // one of the pair on the boundary, the other not
  double area = 0.0;          // |A_j - A_i| / A_i
  double normal = 0.0;        // |n_j - M n_i|
  int facet_count_mismatch = 0;
  double facet_point = 0.0;   // |p - M p'| / cloud size, facets matched by position
  double facet_area = 0.0;    // |a - M a'| / |a|
  std::string worst_volume;   // which pair gave `volume`, for the failure message
};

// The particle at M X_i for every i (-1 when none lies within `tol`), by sorting
// both point sets along the axis and scanning a window: O(n log n).
inline std::vector<std::int32_t> mirror_partner(const Cloud& cloud, const Vec3& centre, int axis, double tol) {
  const int n = static_cast<int>(cloud.size());
  std::vector<std::int32_t> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) { return cloud.X[a][0] < cloud.X[b][0]; });
  std::vector<std::int32_t> partner(n, -1);
  for (int i = 0; i < n; ++i) {
    const Vec3 target = reflect(cloud.X[i], centre, axis);
    auto lo = std::lower_bound(order.begin(), order.end(), target[0] - tol,
                               [&](std::int32_t a, double v) { return cloud.X[a][0] < v; });
    double best = tol;
    for (auto it = lo; it != order.end() && cloud.X[*it][0] <= target[0] + tol; ++it) {
      const double d = (cloud.X[*it] - target).norm();
      if (d <= best) {
        best = d;
        partner[i] = *it;
      }
    }
  }
  return partner;
}

inline MirrorErrors mirror_errors(const Cloud& cloud, const Vec3& centre, int axis) {
  Vec3 lo = cloud.X[0], hi = cloud.X[0];
  for (const Vec3& x : cloud.X) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  const double size = (hi - lo).norm();
  // Generous for matching (a thousandth of a typical spacing would do); the
  // measured position error is what the tests bound.
  const std::vector<std::int32_t> partner = mirror_partner(cloud, centre, axis, 1e-6 * size);

  MirrorErrors e;
  const DualCells cells(cloud);
  std::vector<DualFacet> fi, fj;
  for (std::int32_t i = 0; i < static_cast<std::int32_t>(cloud.size()); ++i) {
    const std::int32_t j = partner[i];
    if (j < 0) {
      ++e.unmatched;
      continue;
    }
    e.position = std::max(e.position, (cloud.X[j] - reflect(cloud.X[i], centre, axis)).norm() / size);
    const double dv = std::abs(cloud.volume[j] - cloud.volume[i]) / cloud.volume[i];
    if (dv > e.volume) {
      e.volume = dv;
      e.worst_volume = "particles " + std::to_string(i) + " and " + std::to_string(j);
    }
    const std::int32_t bi = cloud.boundary_index[i], bj = cloud.boundary_index[j];
    if ((bi < 0) != (bj < 0)) {
      ++e.boundary_mismatch;
    } else if (bi >= 0) {
      e.area = std::max(e.area, std::abs(cloud.boundary_area[bj] - cloud.boundary_area[bi]) / cloud.boundary_area[bi]);
      Vec3 mirrored_normal = cloud.boundary_normal[bi];
      mirrored_normal[axis] = -mirrored_normal[axis];
      e.normal = std::max(e.normal, (cloud.boundary_normal[bj] - mirrored_normal).norm());
    }

    // The facets of j against the mirror images of those of i. A reflection
    // keeps an outward area vector outward: it maps as a vector, a -> M a.
    cells.facets(i, fi);
    cells.facets(j, fj);
    if (fi.size() != fj.size()) {
      ++e.facet_count_mismatch;
      continue;
    }
    for (DualFacet& f : fi) {
      f.point = reflect(f.point, centre, axis);
      f.area[axis] = -f.area[axis];
    }
    // Nearest unused facet by centroid and area vector: no tolerance-free order
    // exists for points that agree only to round-off.
    std::vector<char> used(fj.size(), 0);
    for (const DualFacet& f : fi) {
      std::size_t best = fj.size();
      double best_distance = 1e-6 * size;
      for (std::size_t k = 0; k < fj.size(); ++k) {
        if (used[k]) continue;
        const double d = (fj[k].point - f.point).norm() + (fj[k].area - f.area).norm() / std::sqrt(f.area.norm());
        if (d < best_distance) {
          best_distance = d;
          best = k;
        }
      }
      if (best == fj.size()) {
        ++e.facet_count_mismatch;
        break;
      }
      used[best] = 1;
      e.facet_point = std::max(e.facet_point, (fj[best].point - f.point).norm() / size);
      e.facet_area = std::max(e.facet_area, (fj[best].area - f.area).norm() / f.area.norm());
    }
  }
  return e;
}

}  // namespace rkpm::particles::testing
