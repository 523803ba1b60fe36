// Reproducing conditions of the RK shape functions (VERIFICATION section 1):
// partition of unity, linear reproduction and gradient reproduction to 1e-12
// relative, on every cloud the generators make.
#include "clouds.hpp"
#include "rkpm/rk/rk_approximation.hpp"

#include <gtest/gtest.h>

#include <iostream>

using namespace rkpm;
using namespace rkpm::rk;

namespace {

struct ReproductionErrors {
  double unity = 0, linear = 0, gradient_unity = 0, gradient_linear = 0;
  int points = 0;
};

// Evaluates at every particle and at the midpoints between consecutive particles
// (points strictly inside the body, off the particles).
ReproductionErrors measure(const particles::Cloud& cloud, const RKSettings& settings) {
  RKApproximation rk(cloud, settings);
  const Vec3 lo = [&] { Vec3 m = cloud.X[0]; for (const auto& x : cloud.X) m = m.cwiseMin(x); return m; }();
  const Vec3 hi = [&] { Vec3 m = cloud.X[0]; for (const auto& x : cloud.X) m = m.cwiseMax(x); return m; }();
  const double length = (hi - lo).norm();  // body size: the scale of "relative" for positions
  ReproductionErrors e;
  ShapeValues sv;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    for (int pass = 0; pass < 2; ++pass) {
      const Vec3 x = pass == 0 ? cloud.X[i] : Vec3(0.5 * (cloud.X[i] + cloud.X[(i + 1) % cloud.size()]));
      if (pass == 1 && (cloud.X[i] - cloud.X[(i + 1) % cloud.size()]).norm() > 2.0 * rk.support_radius()[i]) continue;
      rk.evaluate_or_throw(x, sv, true, "test point");
      double pu = 0;
      Vec3 lin = Vec3::Zero(), gpu = Vec3::Zero();
      Mat3 glin = Mat3::Zero();
      for (std::size_t k = 0; k < sv.ids.size(); ++k) {
        const Vec3& XI = cloud.X[static_cast<std::size_t>(sv.ids[k])];
        pu += sv.psi[k];
        lin += sv.psi[k] * XI;
        gpu += sv.grad[k];
        glin += XI * sv.grad[k].transpose();
      }
      const double a = rk.support_radius()[i];
      e.unity = std::max(e.unity, std::abs(pu - 1.0));
      e.linear = std::max(e.linear, (lin - x).norm() / length);
      e.gradient_unity = std::max(e.gradient_unity, gpu.norm() * a);  // grad Psi ~ 1/a
      e.gradient_linear = std::max(e.gradient_linear, (glin - Mat3::Identity()).norm());
      ++e.points;
    }
  }
  return e;
}

void expect_reproducing(const particles::Cloud& cloud, const RKSettings& settings, const char* label) {
  const auto e = measure(cloud, settings);
  std::cout << label << ": " << e.points << " points, max errors: unity " << e.unity << ", linear " << e.linear
            << ", grad unity " << e.gradient_unity << ", grad linear " << e.gradient_linear << "\n";
  EXPECT_LE(e.unity, 1e-12) << label;
  EXPECT_LE(e.linear, 1e-12) << label;
  EXPECT_LE(e.gradient_unity, 1e-12) << label;
  EXPECT_LE(e.gradient_linear, 1e-12) << label;
}

}  // namespace

TEST(Reproducing, JitteredBlockLinearBasis) { expect_reproducing(test::jittered_block(), RKSettings{}, "jittered block"); }

TEST(Reproducing, SphereLinearBasis) { expect_reproducing(test::small_sphere(), RKSettings{}, "sphere"); }

TEST(Reproducing, ShellAtDefaultResolution) { expect_reproducing(test::default_shell(), RKSettings{}, "RBC shell"); }

TEST(Reproducing, QuinticKernel) {
  RKSettings s;
  s.kernel = KernelType::QuinticBSpline;
  expect_reproducing(test::jittered_block(), s, "jittered block, quintic");
}

TEST(Reproducing, QuadraticBasisAlsoReproducesQuadratics) {
  RKSettings s;
  s.basis = Basis::Quadratic;
  s.support = 3.0;
  const auto cloud = test::jittered_block();
  expect_reproducing(cloud, s, "jittered block, quadratic basis");
  // A quadratic field is reproduced exactly too.
  RKApproximation rk(cloud, s);
  ShapeValues sv;
  double worst = 0;
  for (std::size_t i = 0; i < cloud.size(); i += 7) {
    rk.evaluate_or_throw(cloud.X[i], sv, true, "test point");
    double value = 0;
    Vec3 grad = Vec3::Zero();
    for (std::size_t k = 0; k < sv.ids.size(); ++k) {
      const Vec3& X = cloud.X[static_cast<std::size_t>(sv.ids[k])];
      const double f = X.x() * X.y() + 0.5 * X.z() * X.z();
      value += sv.psi[k] * f;
      grad += sv.grad[k] * f;
    }
    const Vec3& x = cloud.X[i];
    worst = std::max(worst, std::abs(value - (x.x() * x.y() + 0.5 * x.z() * x.z())));
    worst = std::max(worst, (grad - Vec3(x.y(), x.x(), x.z())).norm());
  }
  EXPECT_LE(worst, 1e-11);
}

TEST(Reproducing, TooSmallSupportIsReportedWithParticleAndCondition) {
  RKSettings s;
  s.support = 0.6;  // shorter than the spacing: too few particles in reach
  const auto cloud = test::jittered_block(4, 0.0);
  RKApproximation rk(cloud, s);
  ShapeValues sv;
  try {
    rk.evaluate_or_throw(cloud.X[5], sv, false, "particle 5");
    FAIL() << "expected an ApproximationError";
  } catch (const ApproximationError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("particle 5"), std::string::npos) << msg;
    EXPECT_NE(msg.find("moment matrix"), std::string::npos) << msg;
    EXPECT_NE(msg.find("condition number"), std::string::npos) << msg;
  }
}
