// Liquid-crystal elastomer stresses (seed Eq. 1-4 and our compressible
// extension): P = dW/dF, dW/dh, dW/dGrad h, objectivity, the stress-free
// reference state, the torque identity of the skew Cauchy stress.
#include "lce_fixtures.hpp"
#include "support/finite_differences.hpp"
#include "support/random_tensors.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace rkpm::materials {
namespace {

using testing::Rng;

struct Sample {
  Mat3 F;
  DirectorPoint d;
};

// Random deformations (stretch 0.3..3, shear up to 1, J from 0.027 to 27) with
// random unit h, h0 and random Grad_X h, plus the named extremes.
std::vector<Sample> random_samples(Rng& rng, int count) {
  std::vector<Sample> samples;
  const Mat3 extremes[] = {Mat3(Vec3(3.0, 1.0, 1.0).asDiagonal()), Mat3(Vec3(0.3, 1.0, 1.0).asDiagonal()),
                           3.0 * Mat3::Identity(), 0.3 * Mat3::Identity()};
  for (const Mat3& F : extremes)
    samples.push_back({F, {testing::random_unit_vector(rng), testing::random_unit_vector(rng), testing::random_gradient(rng, 1.0)}});
  for (int i = 0; i < count; ++i)
    samples.push_back({testing::random_deformation(rng, 0.3, 3.0, 1.0),
                       {testing::random_unit_vector(rng), testing::random_unit_vector(rng), testing::random_gradient(rng, 1.0)}});
  return samples;
}

const double kAnisotropies[] = {2.0, 0.5, 4.0};

TEST(LiquidCrystalElastomer, FirstPiolaIsEnergyGradient) {
  Rng rng(201);
  for (const double s : kAnisotropies) {
    const auto m = testing::dimensionless_lce(s);
    double worst = 0.0;
    const auto samples = random_samples(rng, 60);
    for (const Sample& x : samples) {
      const Mat3 P = m.first_piola_passive(x.F, x.d);
      const Mat3 P_fd = testing::gradient([&](const Mat3& G) { return m.energy(G, x.d); }, x.F, 1e-4);
      const double error = (P - P_fd).norm() / std::max(P.norm(), m.mu);
      worst = std::max(worst, error);
      EXPECT_LE(error, 1e-6) << "s = " << s << " F =\n" << x.F;
    }
    std::printf("LCE s = %.1f: |P - dW/dF|_fd / |P| over %zu samples: max %.2e\n", s, samples.size(), worst);
  }
}

TEST(LiquidCrystalElastomer, FrankStressIsExercisedAndDerivedFromEnergy) {
  // Without the Frank term the stress changes by O(1): the FD test above would
  // have caught a wrong Frank stress.
  Rng rng(202);
  const auto m = testing::dimensionless_lce(2.0);
  auto no_frank = m;
  no_frank.kappa = 0.0;
  const Sample x = random_samples(rng, 1).back();
  const double frank_part = (m.first_piola_passive(x.F, x.d) - no_frank.first_piola_passive(x.F, x.d)).norm();
  EXPECT_GT(frank_part, 0.05 * m.first_piola_passive(x.F, x.d).norm());
  // sigma_Frank = kf (|G|^2 I - 2 G^T G): the Ericksen stress.
  const Mat3 G = x.d.grad_h * x.F.inverse();
  const Mat3 expected = m.frank_coefficient() * (G.squaredNorm() * Mat3::Identity() - 2.0 * G.transpose() * G);
  const Mat3 got = m.cauchy_passive(x.F, x.d) - no_frank.cauchy_passive(x.F, x.d);
  EXPECT_LE((got - expected).norm(), 1e-12 * expected.norm());
}

TEST(LiquidCrystalElastomer, DirectorDerivativesMatchFiniteDifferences) {
  Rng rng(203);
  for (const double s : kAnisotropies) {
    const auto m = testing::dimensionless_lce(s);
    double worst_h = 0.0, worst_flux = 0.0;
    for (const Sample& x : random_samples(rng, 50)) {
      const Vec3 g = m.director_driving_force(x.F, x.d);
      const Vec3 g_fd = testing::gradient(
          [&](const Vec3& h) {
            DirectorPoint d = x.d;
            d.h = h;
            return m.energy(x.F, d);
          },
          x.d.h, 1e-4);
      const Mat3 flux = m.frank_flux(x.F, x.d);
      const Mat3 flux_fd = testing::gradient(
          [&](const Mat3& A) {
            DirectorPoint d = x.d;
            d.grad_h = A;
            return m.energy(x.F, d);
          },
          x.d.grad_h, 1e-4);
      const double error_h = (g - g_fd).norm() / std::max(g.norm(), m.mu);
      const double error_flux = (flux - flux_fd).norm() / std::max(flux.norm(), m.kappa);
      worst_h = std::max(worst_h, error_h);
      worst_flux = std::max(worst_flux, error_flux);
      EXPECT_LE(error_h, 1e-6);
      EXPECT_LE(error_flux, 1e-6);
    }
    std::printf("LCE s = %.1f: dW/dh error %.2e, dW/dGrad_X h error %.2e (relative, FD)\n", s, worst_h, worst_flux);
  }
}

// The director's energy ledger books W(F, h_new) - W(F, h_old) at fixed F, h0 and
// Grad_X h as the change of the director's share W_h alone (sim/director.cpp). That is
// exact only if nothing else in W depends on h: checked on random states with the
// Frank term on, where a wrong share (a missing (s-1) (h0 . F^T h)^2, or the Frank term
// taken for h-dependent) would leave an O(mu) difference.
TEST(LiquidCrystalElastomer, DirectorShareCarriesTheEnergyChangeOfADirectorUpdate) {
  Rng rng(209);
  for (const double s : kAnisotropies) {
    const auto m = testing::dimensionless_lce(s);
    double worst = 0.0;
    for (const Sample& x : random_samples(rng, 50)) {
      DirectorPoint turned = x.d;
      turned.h = testing::random_unit_vector(rng);
      const double full = m.energy(x.F, turned) - m.energy(x.F, x.d);
      const double share = m.director_energy(x.F, turned.h, x.d.h0) - m.director_energy(x.F, x.d.h, x.d.h0);
      const double scale = std::max({std::abs(m.energy(x.F, turned)), std::abs(m.energy(x.F, x.d)), m.mu});
      const double error = std::abs(full - share) / scale;
      worst = std::max(worst, error);
      EXPECT_LE(error, 1e-12) << "s = " << s << " F =\n" << x.F;
    }
    std::printf("LCE s = %.1f: |dW - dW_h| / |W| over director turns: max %.2e\n", s, worst);
  }
}

TEST(LiquidCrystalElastomer, CauchyIsPushForwardAndSkewPartIsDirectorTorque) {
  Rng rng(204);
  const auto m = testing::dimensionless_lce(2.0);
  double worst_push = 0.0, worst_torque = 0.0;
  for (const Sample& x : random_samples(rng, 50)) {
    const double J = x.F.determinant();
    const Mat3 sigma = m.cauchy(x.F, x.d);
    const Mat3 pushed = m.first_piola(x.F, x.d) * x.F.transpose() / J;
    worst_push = std::max(worst_push, (sigma - pushed).norm() / sigma.norm());
    EXPECT_LE((sigma - pushed).norm(), 1e-12 * sigma.norm());
    // J skew(sigma_passive) = (h g^T - g h^T) / 2, g = dW/dh (angular momentum
    // balance of a nematic; from W(QF, Qh, Q Grad h) = W(F, h, Grad h)).
    const Vec3 g = m.director_driving_force(x.F, x.d);
    const Mat3 sigma_p = m.cauchy_passive(x.F, x.d);
    const Mat3 skew = 0.5 * J * (sigma_p - sigma_p.transpose());
    const Mat3 torque = 0.5 * (x.d.h * g.transpose() - g * x.d.h.transpose());
    worst_torque = std::max(worst_torque, (skew - torque).norm() / std::max(torque.norm(), m.mu));
    EXPECT_LE((skew - torque).norm(), 1e-12 * std::max(torque.norm(), m.mu));
  }
  std::printf("LCE |sigma - P F^T/J| %.2e, |J skew(sigma) - torque| %.2e (relative)\n", worst_push, worst_torque);
}

TEST(LiquidCrystalElastomer, ActiveStressConvention) {
  const auto m = testing::dimensionless_lce(2.0);  // zeta = 0.3 > 0
  const Vec3 h = Vec3(1.0, 2.0, -0.5).normalized();
  // Compressive along h, nothing across it.
  EXPECT_NEAR(h.dot(m.cauchy_active(h) * h), -m.zeta, 1e-15);
  EXPECT_NEAR(h.cross(Vec3::UnitZ()).normalized().dot(m.cauchy_active(h) * h.cross(Vec3::UnitZ()).normalized()), 0.0, 1e-15);
  Rng rng(205);
  const Mat3 F = testing::random_deformation(rng, 0.5, 2.0, 0.5);
  const Mat3 P_a = m.first_piola_active(F, h);
  EXPECT_LE((P_a * F.transpose() / F.determinant() - m.cauchy_active(h)).norm(), 1e-14);
  // Total = passive + active.
  const DirectorPoint d{h, Vec3::UnitX(), Mat3::Zero()};
  EXPECT_LE((m.first_piola(F, d) - m.first_piola_passive(F, d) - P_a).norm(), 1e-13);
}

TEST(LiquidCrystalElastomer, Objectivity) {
  Rng rng(206);
  for (const double s : kAnisotropies) {
    const auto m = testing::dimensionless_lce(s);
    double worst_energy = 0.0, worst_stress = 0.0;
    for (const Sample& x : random_samples(rng, 50)) {
      const Mat3 Q = testing::random_rotation(rng);
      // h and Grad_X h are spatial in their first index; h0 is referential.
      const DirectorPoint rotated{Q * x.d.h, x.d.h0, Q * x.d.grad_h};
      const double W = m.energy(x.F, x.d);
      const double energy_error = std::abs(m.energy(Q * x.F, rotated) - W) / std::max(std::abs(W), m.mu);
      const Mat3 sigma = m.cauchy(x.F, x.d);
      const double stress_error =
          (m.cauchy(Q * x.F, rotated) - Q * sigma * Q.transpose()).norm() / std::max(sigma.norm(), m.mu);
      worst_energy = std::max(worst_energy, energy_error);
      worst_stress = std::max(worst_stress, stress_error);
      EXPECT_LE(energy_error, 1e-12);
      EXPECT_LE(stress_error, 1e-12);
    }
    std::printf("LCE s = %.1f objectivity: energy %.2e, Cauchy %.2e (relative)\n", s, worst_energy, worst_stress);
  }
}

TEST(LiquidCrystalElastomer, ReferenceStateIsExactlyStressFree) {
  Rng rng(207);
  for (const double s : kAnisotropies) {
    auto m = testing::dimensionless_lce(s);
    m.zeta = 0.0;
    for (int i = 0; i < 20; ++i) {
      const Vec3 h0 = testing::random_unit_vector(rng);
      const DirectorPoint d{h0, h0, Mat3::Zero()};
      EXPECT_LE(m.first_piola(Mat3::Identity(), d).norm(), 1e-12 * m.mu);
      EXPECT_LE(m.cauchy(Mat3::Identity(), d).norm(), 1e-12 * m.mu);
      EXPECT_LE(std::abs(m.energy(Mat3::Identity(), d)), 1e-12 * m.mu);
      EXPECT_LE(m.director_rate(Mat3::Identity(), d, Mat3::Zero()).norm(), 1e-12);
    }
    // Rigid rotation with the director carried along: still stress-free, zero energy.
    const Mat3 R = testing::random_rotation(rng);
    const Vec3 h0 = testing::random_unit_vector(rng);
    const DirectorPoint rotated{R * h0, h0, Mat3::Zero()};
    EXPECT_LE(m.cauchy(R, rotated).norm(), 1e-12 * m.mu);
    EXPECT_LE(std::abs(m.energy(R, rotated)), 1e-12 * m.mu);
    EXPECT_LE((m.equilibrium_director(R, h0) - R * h0).norm(), 1e-10);
  }
}

TEST(LiquidCrystalElastomer, SmallStrainModuli) {
  auto m = testing::dimensionless_lce(2.0);
  m.kappa = 0.0;
  m.zeta = 0.0;
  const double e = 1e-7;
  const DirectorPoint d{Vec3::UnitX(), Vec3::UnitX(), Mat3::Zero()};
  // Pure dilation: mean stress / volume strain = K + 2 mu / 3 (K is Lame-like).
  const Mat3 dilation = (1.0 + e) * Mat3::Identity();
  EXPECT_NEAR(m.cauchy(dilation, d).trace() / 3.0 / (3.0 * e), m.K + 2.0 * m.mu / 3.0, 1e-5);
  // Shear in the plane perpendicular to h0 (no director rotation): mu.
  Mat3 shear = Mat3::Identity();
  shear(1, 2) = e;
  EXPECT_NEAR(m.cauchy(shear, d)(1, 2) / e, m.mu, 1e-5);
}

TEST(LiquidCrystalElastomer, ValidationNamesTheBadParameter) {
  auto m = testing::dimensionless_lce(2.0);
  EXPECT_NO_THROW(m.validate());
  m.s = -1.0;
  try {
    m.validate();
    FAIL() << "negative s accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("s = -1"), std::string::npos) << e.what();
  }
  m = testing::dimensionless_lce(2.0);
  m.mu = 0.0;
  EXPECT_THROW(m.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace rkpm::materials
