// Composite 8-point Gauss-Legendre quadrature for the smooth 1-D integrals of the
// ellipsoid geometry (meridian arc length, surface area).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace rkpm::particles::detail {

// Integral of f over [a, b] with panels no wider than max_panel.
template <class F>
double integrate(F&& f, double a, double b, double max_panel) {
  static constexpr double node[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                     0.9602898564975363};
  static constexpr double weight[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                       0.1012285362903763};
  const int panels = std::max(1, static_cast<int>(std::ceil(std::abs(b - a) / max_panel)));
  const double width = (b - a) / panels;
  double sum = 0.0;
  for (int p = 0; p < panels; ++p) {
    const double mid = a + (p + 0.5) * width, half = 0.5 * width;
    for (int k = 0; k < 4; ++k) sum += half * weight[k] * (f(mid - half * node[k]) + f(mid + half * node[k]));
  }
  return sum;
}

}  // namespace rkpm::particles::detail
