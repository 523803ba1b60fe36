// Power-law fit t = c N^p by least squares on log t against log N.
#pragma once

#include <cmath>
#include <vector>

namespace rkpm::scaling {

struct PowerFit {
  double exponent = NAN;
  int points = 0;
};

inline PowerFit fit_power_law(const std::vector<double>& n, const std::vector<double>& t) {
  PowerFit fit;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (!(n[i] > 0) || !(t[i] > 0)) continue;
    const double x = std::log(n[i]), y = std::log(t[i]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
    ++fit.points;
  }
  const double k = fit.points, det = k * sxx - sx * sx;
  if (fit.points >= 2 && det > 0) fit.exponent = (k * sxy - sx * sy) / det;
  return fit;
}

}  // namespace rkpm::scaling
