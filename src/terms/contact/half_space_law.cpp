#include "terms/contact/half_space_law.hpp"

#include <cmath>

namespace rkpm::sim {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Antiderivatives in r of r^(1-n) (r - D)^2, r^(1-n) (r - D) and r^(1-n) for the three
// powers of phi_s: n = 12, n = 6 and the constant shift (n = 0).
double energy_antiderivative(int n, double r, double D) {
  const double a = 4 - n, b = 3 - n, c = 2 - n;
  return std::pow(r, a) / a - 2.0 * D * std::pow(r, b) / b + D * D * std::pow(r, c) / c;
}
double traction_antiderivative(int n, double r, double D) {
  const double b = 3 - n, c = 2 - n;
  return std::pow(r, b) / b - D * std::pow(r, c) / c;
}
double slope_antiderivative(int n, double r) {
  const double c = 2 - n;
  return std::pow(r, c) / c;
}

}  // namespace

HalfSpaceLaw::HalfSpaceLaw(double epsilon, double s0, double cutoff)
    : c12_(epsilon * std::pow(s0, 12)), c6_(2.0 * epsilon * std::pow(s0, 6)), rc_(cutoff) {
  shift_ = c12_ * std::pow(rc_, -12) - c6_ * std::pow(rc_, -6);
}

double HalfSpaceLaw::energy(double D) const {
  if (D >= rc_) return 0.0;
  const auto part = [&](int n) { return energy_antiderivative(n, rc_, D) - energy_antiderivative(n, D, D); };
  return kPi * (c12_ * part(12) - c6_ * part(6) - shift_ * part(0));
}

double HalfSpaceLaw::traction(double D) const {
  if (D >= rc_) return 0.0;
  const auto part = [&](int n) { return traction_antiderivative(n, rc_, D) - traction_antiderivative(n, D, D); };
  return 2.0 * kPi * (c12_ * part(12) - c6_ * part(6) - shift_ * part(0));
}

double HalfSpaceLaw::traction_slope(double D) const {
  if (D >= rc_) return 0.0;
  const auto part = [&](int n) { return slope_antiderivative(n, rc_) - slope_antiderivative(n, D); };
  return -2.0 * kPi * (c12_ * part(12) - c6_ * part(6) - shift_ * part(0));
}

}  // namespace rkpm::sim
