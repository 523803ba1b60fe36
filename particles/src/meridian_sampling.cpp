#include "meridian_sampling.hpp"

#include "gauss_legendre.hpp"

#include <algorithm>
#include <cmath>

namespace rkpm::particles::detail {
namespace {

// Table intervals of pi/128: one 8-point Gauss panel each integrates the speed
// to machine precision even for flat spheroids, whose integrand has complex
// singularities at distance atanh(c/rho) (0.22 for the seed's inner surface).
constexpr int kIntervals = 64;
constexpr double kStep = 0.5 * M_PI / kIntervals;

}  // namespace

MeridianSampling::MeridianSampling(double rho, double c, double turning_weight)
    : rho_(rho), c_(c), w_(turning_weight), cumulative_(kIntervals + 1, 0.0) {
  for (int k = 0; k < kIntervals; ++k) {
    cumulative_[k + 1] = cumulative_[k] + integrate([this](double p) { return speed(p); }, k * kStep, (k + 1) * kStep, kStep);
  }
  quarter_arc_ = cumulative_.back();
}

double MeridianSampling::speed(double psi) const {
  const double co = std::cos(psi), si = std::sin(psi);
  return std::sqrt(rho_ * rho_ * co * co + c_ * c_ * si * si);
}

double MeridianSampling::arc_from_pole(double psi) const {
  const int k = std::min(kIntervals - 1, static_cast<int>(psi / kStep));
  return cumulative_[k] + integrate([this](double p) { return speed(p); }, k * kStep, psi, kStep);
}

double MeridianSampling::blend(double psi) const {
  const double beta = std::atan2(c_ * std::sin(psi), rho_ * std::cos(psi));
  return (1.0 - w_) * arc_from_pole(psi) / quarter_arc_ + w_ * beta / (0.5 * M_PI);
}

double MeridianSampling::blend_rate(double psi) const {
  // d beta / d psi = rho c / speed^2 (curvature times speed).
  const double v = speed(psi);
  return (1.0 - w_) * v / quarter_arc_ + w_ * rho_ * c_ / (v * v) / (0.5 * M_PI);
}

double MeridianSampling::psi(double theta) const {
  if (theta > 0.5 * M_PI) return M_PI - psi(M_PI - theta);  // mirror symmetry about the equator
  if (theta <= 0.0) return 0.0;
  const double target = theta / (0.5 * M_PI);
  // Newton on the increasing g(psi) = target, kept inside a shrinking bracket
  // (bisection when a step would leave it): g bends sharply at a flat rim, where
  // plain Newton can overshoot.
  // Steps of 1e-14 are at the rounding level of g (a sum of quadrature panels), so
  // the iteration stops there instead of wandering in the noise.
  double lo = 0.0, hi = 0.5 * M_PI, psi = theta;
  for (int it = 0; it < 100; ++it) {
    const double residual = blend(psi) - target;
    if (residual == 0.0) break;
    if (residual < 0.0) lo = psi;
    else hi = psi;
    double next = psi - residual / blend_rate(psi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const bool converged = std::abs(next - psi) <= 1e-14;
    psi = next;
    if (converged) break;
  }
  return psi;
}

}  // namespace rkpm::particles::detail
