#include "rkpm/rk/kernel.hpp"

#include <gtest/gtest.h>

using namespace rkpm::rk;

namespace {
void expect_smooth_spline(KernelType type) {
  // Zero at and beyond the support edge, positive inside, derivative consistent with
  // the value (central differences), and continuous (with its derivative) at knots.
  EXPECT_EQ(evaluate_kernel(type, 1.0).w, 0.0);
  EXPECT_EQ(evaluate_kernel(type, 1.5).w, 0.0);
  EXPECT_NEAR(evaluate_kernel(type, 0.0).dw_dq, 0.0, 1e-14);
  for (double q = 0.01; q < 1.0; q += 0.01) {
    const double h = 1e-6;
    const double fd = (evaluate_kernel(type, q + h).w - evaluate_kernel(type, q - h).w) / (2 * h);
    EXPECT_GT(evaluate_kernel(type, q).w, 0.0) << q;
    EXPECT_NEAR(evaluate_kernel(type, q).dw_dq, fd, 1e-7 * std::abs(evaluate_kernel(type, 0).w) + 1e-8) << q;
  }
  // Second derivative continuous too (C2 at least): compare one-sided second differences near knots.
  const double knots3[] = {1.0 / 3.0, 2.0 / 3.0};
  const double knots2[] = {0.5};
  const double* knots = type == KernelType::CubicBSpline ? knots2 : knots3;
  const int nk = type == KernelType::CubicBSpline ? 1 : 2;
  for (int i = 0; i < nk; ++i) {
    const double k = knots[i], h = 1e-4;
    const double left = (evaluate_kernel(type, k).dw_dq - evaluate_kernel(type, k - h).dw_dq) / h;
    const double right = (evaluate_kernel(type, k + h).dw_dq - evaluate_kernel(type, k).dw_dq) / h;
    EXPECT_NEAR(left, right, 1e-2 * std::abs(left) + 1e-3) << "second derivative jumps at q = " << k;
  }
}
}  // namespace

TEST(Kernel, CubicBSplineIsSmoothWithUnitSupport) { expect_smooth_spline(KernelType::CubicBSpline); }
TEST(Kernel, QuinticBSplineIsSmoothWithUnitSupport) { expect_smooth_spline(KernelType::QuinticBSpline); }
