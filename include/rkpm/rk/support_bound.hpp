// The largest support radius near a point, from a coarse grid over the particles.
//
// A particle I can reach a point within `reach` of c only if |X_I - c| < a_I + reach,
// so a neighbour query around c needs the radius max a_I + reach over the particles
// near c. Taking the maximum over the whole cloud instead made every query of a cloud
// with graded supports (a mapped ball, a shell) reach as far as its largest support
// everywhere and return far more points than it needed (docs/verification/performance.md
// measures the set-up). The grid holds each cell's largest a_I;
// `near(c, reach)` is the largest over the cells that the cube of half-width
// a_max + reach around c touches, an upper bound for every particle that can matter.
#pragma once

#include "rkpm/common/types.hpp"

#include <array>
#include <vector>

namespace rkpm::rk {

class SupportBound {
 public:
  SupportBound() = default;
  // a[I] is particle I's support radius (positive); X and a have the same length.
  SupportBound(const std::vector<Vec3>& X, const std::vector<double>& a);

  // An upper bound of a_I over every particle with |X_I - c| < a_I + reach.
  double near(const Vec3& c, double reach) const;

 private:
  int cell_index(int axis, double coordinate) const;

  double a_max_ = 0.0;
  Vec3 origin_ = Vec3::Zero();
  double cell_ = 1.0;
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<double> cell_max_;
};

}  // namespace rkpm::rk
