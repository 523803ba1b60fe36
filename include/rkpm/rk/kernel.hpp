// Kernel functions of the reproducing-kernel approximation.
//
// The support is a sphere: phi_a(x - X_I) = w(|x - X_I| / a_I), zero for q >= 1, so a
// particle's kernel covers the ball of radius a_I (its "support radius") around it.
// w is a B-spline written on the normalised distance q in [0, 1]; its normalisation
// is irrelevant because the RK correction restores the reproducing conditions.
#pragma once

namespace rkpm::rk {

enum class KernelType { CubicBSpline, QuinticBSpline };

struct KernelValue {
  double w;      // w(q)
  double dw_dq;  // dw/dq
};

// Cubic B-spline (C2), knots at q = 0, 1/2, 1.
inline KernelValue cubic_bspline(double q) {
  if (q >= 1.0) return {0.0, 0.0};
  if (q <= 0.5) return {2.0 / 3.0 - 4.0 * q * q + 4.0 * q * q * q, -8.0 * q + 12.0 * q * q};
  const double r = 1.0 - q;
  return {4.0 / 3.0 * r * r * r, -4.0 * r * r};
}

// Quintic B-spline (C4), knots at q = 0, 1/3, 2/3, 1 (the standard 3h-support spline
// rescaled to unit support).
inline KernelValue quintic_bspline(double q) {
  if (q >= 1.0) return {0.0, 0.0};
  const double s = 3.0 * q;
  auto p5 = [](double x) { return x * x * x * x * x; };
  auto p4 = [](double x) { return x * x * x * x; };
  double w = p5(3.0 - s);
  double d = -5.0 * p4(3.0 - s);
  if (s < 2.0) {
    w -= 6.0 * p5(2.0 - s);
    d += 30.0 * p4(2.0 - s);
  }
  if (s < 1.0) {
    w += 15.0 * p5(1.0 - s);
    d -= 75.0 * p4(1.0 - s);
  }
  return {w / 120.0, d * 3.0 / 120.0};
}

inline KernelValue evaluate_kernel(KernelType type, double q) {
  return type == KernelType::CubicBSpline ? cubic_bspline(q) : quintic_bspline(q);
}

}  // namespace rkpm::rk
