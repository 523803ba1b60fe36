#include "rkpm/rk/ellipsoid_grid.hpp"

#include <algorithm>
#include <cmath>

namespace rkpm::rk {

SupportsBox supports_box(const std::vector<Vec3>& X, const std::vector<double>& radius) {
  SupportsBox box{X.front(), X.front(), 0.0};
  for (std::size_t i = 0; i < X.size(); ++i) {
    box.lo = box.lo.cwiseMin(X[i]);
    box.hi = box.hi.cwiseMax(X[i]);
    box.a_max = std::max(box.a_max, radius[i]);
  }
  return box;
}

EllipsoidGrid::EllipsoidGrid(const std::vector<Vec3>& X, const std::vector<SymmetricEntries>& metric,
                             const std::vector<double>& radius, const std::vector<double>& min_axis,
                             double bucket_fraction) {
  const std::size_t n = X.size();
  if (n == 0) return;
  const auto [lo, hi, a_max] = supports_box(X, radius);
  origin_ = lo;
  const Vec3 extent = hi - lo;

  // Buckets of a fraction of the median shortest semi-axis (half: a few particles each),
  // at most about four per particle: a thin shell fills little of its bounding box.
  std::vector<double> shortest(min_axis);
  std::nth_element(shortest.begin(), shortest.begin() + static_cast<std::ptrdiff_t>(n / 2), shortest.end());
  bucket_ = bucket_fraction * shortest[n / 2];
  const auto count = [&](double side) {
    double total = 1.0;
    for (int k = 0; k < 3; ++k) total *= std::floor(extent(k) / side) + 1.0;
    return total;
  };
  while (count(bucket_) > 4.0 * static_cast<double>(n) + 8.0) bucket_ *= 1.25;
  // Coarse cells of at least 1.5 a_max: a query's reach may then be up to C - a_max.
  per_coarse_ = std::max(1, static_cast<int>(std::ceil(1.5 * a_max / bucket_)));
  max_reach_ = per_coarse_ * bucket_ - a_max;
  inverse_bucket_ = 1.0 / bucket_;
  for (int k = 0; k < 3; ++k) {
    dims_[k] = static_cast<int>(std::floor(extent(k) / bucket_)) + 1;
    coarse_dims_[k] = (dims_[k] + per_coarse_ - 1) / per_coarse_;
  }

  // Counting sort of the particles by bucket; within a bucket by id.
  const std::size_t buckets = static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2];
  std::vector<std::uint32_t> bucket_of(n);
  start_.assign(buckets + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto b = (static_cast<std::size_t>(bucket_index(2, X[i].z())) * dims_[1] + bucket_index(1, X[i].y())) *
                       dims_[0] +
                   bucket_index(0, X[i].x());
    bucket_of[i] = static_cast<std::uint32_t>(b);
    ++start_[b + 1];
  }
  for (std::size_t b = 0; b < buckets; ++b) start_[b + 1] += start_[b];
  order_.resize(n);
  {
    std::vector<std::uint32_t> next(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < n; ++i) order_[next[bucket_of[i]]++] = static_cast<Index>(i);
  }
  inv_min_axis_.resize(n);
  for (auto& g : g_) g.resize(n);
  double worst_condition = 1.0;  // of G_J: (longest / shortest semi-axis)^2
  for (std::size_t k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(order_[k]);
    inv_min_axis_[k] = static_cast<float>(1.0 / min_axis[i]);
    for (int c = 0; c < 6; ++c) g_[c][k] = static_cast<float>(metric[i][c]);
    worst_condition = std::max(worst_condition, radius[i] * radius[i] / (min_axis[i] * min_axis[i]));
  }
  // r^T G r from entries rounded to float differs from the exact form by at most a few
  // float epsilons (6e-8) times sum |G_ij r_i r_j| <= 3 lambda_max |r|^2 <= 3 cond q^2.
  test_slack_ = 1e-6 * worst_condition;

  // Each coarse cell's largest spans, then the largest over its neighbourhood.
  const std::size_t coarse = static_cast<std::size_t>(coarse_dims_[0]) * coarse_dims_[1] * coarse_dims_[2];
  std::vector<std::array<double, 3>> own(coarse, std::array<double, 3>{});
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k =
        coarse_of_bucket(bucket_index(0, X[i].x()), bucket_index(1, X[i].y()), bucket_index(2, X[i].z()));
    // (G^-1)_ii from the cofactors: G is symmetric positive definite.
    const auto& g = metric[i];  // 00, 11, 22, 01, 02, 12
    const double c00 = g[1] * g[2] - g[5] * g[5];
    const double c11 = g[0] * g[2] - g[4] * g[4];
    const double c22 = g[0] * g[1] - g[3] * g[3];
    const double det = g[0] * c00 - g[3] * (g[3] * g[2] - g[5] * g[4]) + g[4] * (g[3] * g[5] - g[1] * g[4]);
    const std::array<double, 3> span{std::sqrt(c00 / det), std::sqrt(c11 / det), std::sqrt(c22 / det)};
    for (int a = 0; a < 3; ++a) own[k][a] = std::max(own[k][a], std::min(span[a], radius[i]));
  }
  spans_.assign(coarse, std::array<double, 3>{});
  for (int cz = 0; cz < coarse_dims_[2]; ++cz)
    for (int cy = 0; cy < coarse_dims_[1]; ++cy)
      for (int cx = 0; cx < coarse_dims_[0]; ++cx) {
        auto& span = spans_[(static_cast<std::size_t>(cz) * coarse_dims_[1] + cy) * coarse_dims_[0] + cx];
        for (int z = std::max(0, cz - 1); z <= std::min(coarse_dims_[2] - 1, cz + 1); ++z)
          for (int y = std::max(0, cy - 1); y <= std::min(coarse_dims_[1] - 1, cy + 1); ++y)
            for (int x = std::max(0, cx - 1); x <= std::min(coarse_dims_[0] - 1, cx + 1); ++x) {
              const auto& o = own[(static_cast<std::size_t>(z) * coarse_dims_[1] + y) * coarse_dims_[0] + x];
              for (int a = 0; a < 3; ++a) span[a] = std::max(span[a], o[a]);
            }
        // Rounding of the cofactors: a relative margin far above it.
        for (auto& s : span) s *= 1.0 + 1e-9;
      }
}

int EllipsoidGrid::bucket_index(int axis, double coordinate) const {
  // A product, not a quotient (a query's rows ask for two indices each): the index is
  // still monotone in the coordinate, which is all the ranges need.
  const double t = std::floor((coordinate - origin_(axis)) * inverse_bucket_);
  return static_cast<int>(std::clamp(t, 0.0, static_cast<double>(dims_[axis] - 1)));
}

std::size_t EllipsoidGrid::coarse_of_bucket(int bx, int by, int bz) const {
  return (static_cast<std::size_t>(bz / per_coarse_) * coarse_dims_[1] + by / per_coarse_) * coarse_dims_[0] +
         bx / per_coarse_;
}

const std::array<double, 3>& EllipsoidGrid::spans_near(const Vec3& c) const {
  return spans_[coarse_of_bucket(bucket_index(0, c.x()), bucket_index(1, c.y()), bucket_index(2, c.z()))];
}

void EllipsoidGrid::ranges(const Vec3& c, const Vec3& reach_along, double ball,
                           std::vector<std::pair<std::uint32_t, std::uint32_t>>& out) const {
  out.clear();
  if (order_.empty()) return;
  // A point outside the grid takes the nearest coarse cell: every particle within C of
  // it lies in that cell's neighbourhood too.
  const auto& span = spans_near(c);
  std::array<int, 3> lo{}, hi{};
  for (int a = 0; a < 3; ++a) {
    if (!(span[a] > 0.0)) return;  // no particle near
    const double half = std::min((span[a] + reach_along(a)) * (1.0 + 1e-9), ball);
    lo[a] = bucket_index(a, c(a) - half);
    hi[a] = bucket_index(a, c(a) + half);
  }
  // The distance from c to the nearest point of a bucket's span along one axis.
  const auto gap = [&](int axis, int index) {
    const double from = origin_(axis) + index * bucket_, to = from + bucket_;
    return c(axis) < from ? from - c(axis) : (c(axis) > to ? c(axis) - to : 0.0);
  };
  const double ball2 = ball * ball;
  for (int z = lo[2]; z <= hi[2]; ++z) {
    const double gz = gap(2, z);
    for (int y = lo[1]; y <= hi[1]; ++y) {
      const double gy = gap(1, y);
      // Each row also trimmed to the ball's chord through its nearest line to c.
      const double chord2 = ball2 - gy * gy - gz * gz;
      if (chord2 < 0.0) continue;
      const double chord = std::sqrt(chord2);
      const int from = std::max(lo[0], bucket_index(0, c.x() - chord));
      const int to = std::min(hi[0], bucket_index(0, c.x() + chord));
      if (from > to) continue;
      const std::size_t row = (static_cast<std::size_t>(z) * dims_[1] + y) * dims_[0];
      const std::uint32_t first = start_[row + from], last = start_[row + to + 1];
      if (first < last) out.emplace_back(first, last);
    }
  }
}

}  // namespace rkpm::rk
