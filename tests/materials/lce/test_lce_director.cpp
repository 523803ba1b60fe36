// Director law of the liquid-crystal elastomer (seed Eq. 5-7): relaxation rate,
// co-rotation with the spin, the Frank term's entry, the equilibrium director.
#include "lce_fixtures.hpp"
#include "support/random_tensors.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace rkpm::materials {
namespace {

// Classical RK4 step of dh/dt = director_rate(F, h, l = 0).
Vec3 rk4_step(const LiquidCrystalElastomer& m, const Mat3& F, DirectorPoint d, double dt) {
  const Vec3 h = d.h;
  const auto rate = [&](const Vec3& hh) {
    d.h = hh;
    return m.director_rate(F, d, Mat3::Zero());
  };
  const Vec3 k1 = rate(h);
  const Vec3 k2 = rate(h + 0.5 * dt * k1);
  const Vec3 k3 = rate(h + 0.5 * dt * k2);
  const Vec3 k4 = rate(h + dt * k3);
  return h + (dt / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

TEST(LceDirector, RelaxationAtIdentityFollowsTheClosedForm) {
  for (const double s : {2.0, 3.0}) {
    auto m = testing::dimensionless_lce(s);
    m.mu = 2.5;
    m.mobility = 0.4;
    const double k = m.mobility * m.mu * (s - 1.0) * (s - 1.0) / s;  // VERIFICATION section 3
    const double theta0 = 1.2;                                       // rad from h0 = e1
    DirectorPoint d{Vec3(std::cos(theta0), std::sin(theta0), 0.0), Vec3::UnitX(), Mat3::Zero()};
    const double dt = 0.005 / k;
    double worst = 0.0, drift = 0.0;
    const int steps = static_cast<int>(std::lround(4.0 / (k * dt)));  // four relaxation times
    for (int n = 1; n <= steps; ++n) {
      d.h = rk4_step(m, Mat3::Identity(), d, dt);
      const double t = n * dt;
      const double tan_theta = std::abs(d.h.y()) / std::abs(d.h.x());
      const double expected = std::tan(theta0) * std::exp(-k * t);
      worst = std::max(worst, std::abs(tan_theta - expected) / expected);
      drift = std::max(drift, std::abs(d.h.norm() - 1.0));
      EXPECT_NEAR(d.h.z(), 0.0, 1e-14);
    }
    std::printf("director relaxation s = %.0f over 4/k: max relative error of tan(theta) %.2e, max ||h|-1| %.2e\n", s,
                worst, drift);
    EXPECT_LE(worst, 1e-2);
    EXPECT_LE(drift, 1e-6);
  }
}

TEST(LceDirector, ConvectiveTermOfEquation7) {
  const auto m = testing::dimensionless_lce(2.0);
  testing::Rng rng(301);
  const Vec3 h0 = testing::random_unit_vector(rng);
  const DirectorPoint d{h0, h0, Mat3::Zero()};  // equilibrium at F = I: no relaxation
  Mat3 l;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) l(i, j) = rng.uniform(-1, 1);
  const Mat3 w = 0.5 * (l - l.transpose());
  const Mat3 D = 0.5 * (l + l.transpose());
  // Rigid spin: the director turns with the material, dh/dt = w h.
  EXPECT_LE((m.director_rate(Mat3::Identity(), d, w) - w * h0).norm(), 1e-14);
  // Stretching: Eq. 7 as written gives dh/dt = -(1/2) D h.
  EXPECT_LE((m.director_rate(Mat3::Identity(), d, D) + 0.5 * D * h0).norm(), 1e-14);
}

TEST(LceDirector, FrankDivergenceEntersAsAProjectedForce) {
  const auto m = testing::dimensionless_lce(2.0);
  const DirectorPoint d{Vec3::UnitX(), Vec3::UnitX(), Mat3::Zero()};
  const Vec3 divergence(0.7, -0.2, 0.4);
  // dF/dh = dW/dh - Div(flux); at equilibrium dW/dh is along h and projected away.
  const Vec3 rate = m.director_rate(Mat3::Identity(), d, Mat3::Zero(), divergence);
  EXPECT_LE((rate - m.mobility * Vec3(0.0, -0.2, 0.4)).norm(), 1e-14);
}

TEST(LceDirector, EquilibriumDirectorMinimisesEnergy) {
  testing::Rng rng(302);
  for (const double s : {2.0, 0.5}) {
    auto m = testing::dimensionless_lce(s);
    m.kappa = 0.0;
    double worst_torque = 0.0;
    for (int i = 0; i < 50; ++i) {
      const Mat3 F = testing::random_deformation(rng, 0.5, 2.0, 0.5);
      const Vec3 h0 = testing::random_unit_vector(rng);
      DirectorPoint d{m.equilibrium_director(F, h0), h0, Mat3::Zero()};
      EXPECT_NEAR(d.h.norm(), 1.0, 1e-14);
      EXPECT_GE(d.h.dot(F * h0), 0.0);
      const double W_eq = m.energy(F, d);
      // The projected driving force (torque) vanishes ...
      const Vec3 g = m.director_driving_force(F, d);
      const double torque = (g - d.h * d.h.dot(g)).norm() / std::max(g.norm(), m.mu);
      worst_torque = std::max(worst_torque, torque);
      EXPECT_LE(torque, 1e-12);
      // ... and no other unit director has lower energy.
      for (int j = 0; j < 200; ++j) {
        DirectorPoint other = d;
        other.h = testing::random_unit_vector(rng);
        EXPECT_GE(m.energy(F, other), W_eq - 1e-12);
      }
    }
    std::printf("equilibrium director s = %.1f: max relative torque %.2e\n", s, worst_torque);
  }
}

}  // namespace
}  // namespace rkpm::materials
