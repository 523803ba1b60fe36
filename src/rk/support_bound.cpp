#include "rkpm/rk/support_bound.hpp"

#include <algorithm>
#include <cmath>

namespace rkpm::rk {

SupportBound::SupportBound(const std::vector<Vec3>& X, const std::vector<double>& a) {
  if (X.empty()) return;
  Vec3 lo = X.front(), hi = X.front();
  for (std::size_t i = 0; i < X.size(); ++i) {
    lo = lo.cwiseMin(X[i]);
    hi = hi.cwiseMax(X[i]);
    a_max_ = std::max(a_max_, a[i]);
  }
  // Cells of the largest support's size, at most about one per particle.
  cell_ = a_max_;
  const Vec3 extent = hi - lo;
  const auto count = [&](double cell) {
    double total = 1.0;
    for (int k = 0; k < 3; ++k) total *= std::floor(extent(k) / cell) + 1.0;
    return total;
  };
  while (count(cell_) > static_cast<double>(X.size()) + 1.0) cell_ *= 2.0;
  origin_ = lo;
  for (int k = 0; k < 3; ++k) dims_[k] = static_cast<int>(std::floor(extent(k) / cell_)) + 1;
  cell_max_.assign(static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2], 0.0);
  for (std::size_t i = 0; i < X.size(); ++i) {
    const std::size_t c = (static_cast<std::size_t>(cell_index(2, X[i].z())) * dims_[1] + cell_index(1, X[i].y())) *
                              dims_[0] +
                          cell_index(0, X[i].x());
    cell_max_[c] = std::max(cell_max_[c], a[i]);
  }
}

int SupportBound::cell_index(int axis, double coordinate) const {
  const double t = std::floor((coordinate - origin_(axis)) / cell_);
  return static_cast<int>(std::clamp(t, 0.0, static_cast<double>(dims_[axis] - 1)));
}

double SupportBound::near(const Vec3& c, double reach) const {
  if (cell_max_.empty()) return a_max_;
  const double half = a_max_ + reach;
  std::array<int, 3> lo{}, hi{};
  for (int k = 0; k < 3; ++k) {
    lo[k] = cell_index(k, c(k) - half);
    hi[k] = cell_index(k, c(k) + half);
  }
  double bound = 0.0;
  for (int z = lo[2]; z <= hi[2]; ++z)
    for (int y = lo[1]; y <= hi[1]; ++y) {
      const double* row = &cell_max_[(static_cast<std::size_t>(z) * dims_[1] + y) * dims_[0]];
      for (int x = lo[0]; x <= hi[0]; ++x) bound = std::max(bound, row[x]);
    }
  return bound;
}

}  // namespace rkpm::rk
