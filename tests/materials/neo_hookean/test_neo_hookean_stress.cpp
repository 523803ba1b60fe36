// Compressible neo-Hookean solid: stress-free reference, closed forms for uniaxial
// and simple-shear states, P = dW/dF by finite differences, objectivity, the
// small-strain moduli and the validation messages.
#include "materials/neo_hookean/neo_hookean.hpp"

#include "support/finite_differences.hpp"
#include "support/random_tensors.hpp"
#include "support/solvers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace rkpm::materials {
namespace {

using testing::Rng;

const NeoHookean kGel{1.5e3, 6.0e3};  // mu, lambda [Pa]: Poisson's ratio 0.4

std::vector<Mat3> sample_deformations(Rng& rng, int random_count) {
  std::vector<Mat3> Fs;
  Fs.push_back(Mat3::Identity());
  Fs.push_back(Vec3(3.0, 1.0, 1.0).asDiagonal());
  Fs.push_back(Vec3(0.3, 1.0, 1.0).asDiagonal());
  Fs.push_back(3.0 * Mat3::Identity());  // J = 27
  Fs.push_back(0.3 * Mat3::Identity());  // J = 0.027
  for (int i = 0; i < random_count; ++i) Fs.push_back(testing::random_deformation(rng, 0.3, 3.0, 1.0));
  return Fs;
}

TEST(NeoHookean, ReferenceStateIsStressFree) {
  EXPECT_EQ(kGel.first_piola(Mat3::Identity()).norm(), 0.0);
  EXPECT_EQ(kGel.cauchy(Mat3::Identity()).norm(), 0.0);
  EXPECT_EQ(kGel.energy(Mat3::Identity()), 0.0);
}

// F = diag(l, t, t) with t prescribed: J = l t^2,
//   W = mu/2 (l^2 + 2 t^2 - 3) - mu ln J + lambda/2 (ln J)^2,
//   P_11 = mu (l - 1/l) + lambda ln J / l,   P_22 = P_33 = mu (t - 1/t) + lambda ln J / t.
TEST(NeoHookean, StretchWithFixedLateralStretchMatchesClosedForm) {
  const double mu = kGel.mu, lambda = kGel.lambda;
  for (const double l : {0.5, 0.9, 1.2, 2.5}) {
    for (const double t : {0.7, 1.0, 1.3}) {
      const Mat3 F = Vec3(l, t, t).asDiagonal();
      const double log_J = std::log(l * t * t);
      const double W = 0.5 * mu * (l * l + 2.0 * t * t - 3.0) - mu * log_J + 0.5 * lambda * log_J * log_J;
      const double P11 = mu * (l - 1.0 / l) + lambda * log_J / l;
      const double P22 = mu * (t - 1.0 / t) + lambda * log_J / t;
      const Mat3 P = kGel.first_piola(F);
      const double scale = std::max({std::abs(P11), std::abs(P22), mu});
      EXPECT_NEAR(kGel.energy(F), W, 1e-13 * std::max(std::abs(W), mu));
      EXPECT_NEAR(P(0, 0), P11, 1e-13 * scale);
      EXPECT_NEAR(P(1, 1), P22, 1e-13 * scale);
      EXPECT_NEAR(P(2, 2), P22, 1e-13 * scale);
      EXPECT_LE((P - Mat3(P.diagonal().asDiagonal())).norm(), 1e-13 * scale);
    }
  }
}

// Uniaxial stress along e1: the lateral stretch t solves the closed-form condition
// P_22 = 0, i.e. mu (t^2 - 1) + lambda ln(l t^2) = 0; then sigma_22 = 0 and
// sigma_11 = mu (l^2 - t^2) / J.
TEST(NeoHookean, UniaxialStressMatchesClosedForm) {
  const double mu = kGel.mu, lambda = kGel.lambda;
  for (const double l : {0.6, 1.1, 1.5, 2.0}) {
    // The condition divided by mu, so the tolerance is relative to the moduli.
    const double t = testing::solve_root(
        [&](double s) { return (s * s - 1.0) + (lambda / mu) * std::log(l * s * s); }, 1.0, 1e-14);
    const Mat3 F = Vec3(l, t, t).asDiagonal();
    const double J = l * t * t;
    const Mat3 sigma = kGel.cauchy(F);
    const double sigma11 = mu * (l * l - t * t) / J;
    std::printf("neo-Hookean uniaxial l = %.1f: t = %.7f, sigma11 = %.6f Pa (closed form %.6f)\n", l, t, sigma(0, 0),
                sigma11);
    EXPECT_NEAR(sigma(0, 0), sigma11, 1e-10 * std::abs(sigma11));
    EXPECT_NEAR(sigma(1, 1), 0.0, 1e-9 * std::abs(sigma11));
    EXPECT_NEAR(sigma(2, 2), 0.0, 1e-9 * std::abs(sigma11));
    // Lateral contraction below incompressibility's 1/sqrt(l) for l > 1 (the solid is compressible).
    if (l > 1.0) {
      EXPECT_GT(t, 1.0 / std::sqrt(l));
    }
  }
}

// Simple shear F = I + gamma e1 (x) e2 (J = 1): P_12 = P_21 = mu gamma,
// P_11 = P_22 = P_33 = 0, W = mu gamma^2 / 2, sigma_11 = mu gamma^2.
TEST(NeoHookean, SimpleShearMatchesClosedForm) {
  const double mu = kGel.mu;
  for (const double gamma : {0.01, 0.5, 2.0}) {
    Mat3 F = Mat3::Identity();
    F(0, 1) = gamma;
    Mat3 expected = Mat3::Zero();
    expected(0, 1) = expected(1, 0) = mu * gamma;
    EXPECT_LE((kGel.first_piola(F) - expected).norm(), 1e-12 * mu * std::max(1.0, gamma));
    EXPECT_NEAR(kGel.energy(F), 0.5 * mu * gamma * gamma, 1e-12 * mu);
    EXPECT_NEAR(kGel.cauchy(F)(0, 0), mu * gamma * gamma, 1e-12 * mu * std::max(1.0, gamma * gamma));
    EXPECT_NEAR(kGel.cauchy(F)(0, 1), mu * gamma, 1e-12 * mu * std::max(1.0, gamma));
  }
}

TEST(NeoHookean, FirstPiolaIsEnergyGradient) {
  Rng rng(701);
  double worst = 0.0;
  const auto Fs = sample_deformations(rng, 60);
  for (const Mat3& F : Fs) {
    const Mat3 P = kGel.first_piola(F);
    // Fourth-order differences: truncation ~ step^4, round-off ~ eps W / step.
    const Mat3 P_fd = testing::gradient([&](const Mat3& G) { return kGel.energy(G); }, F, 1e-4);
    const double error = (P - P_fd).norm() / std::max(P.norm(), kGel.mu);
    worst = std::max(worst, error);
    EXPECT_LE(error, 1e-7) << "F =\n" << F;
  }
  std::printf("neo-Hookean |P - dW/dF|_fd / |P| over %zu deformations: max %.2e\n", Fs.size(), worst);
}

TEST(NeoHookean, CauchyMatchesPushForwardOfFirstPiola) {
  Rng rng(702);
  for (const Mat3& F : sample_deformations(rng, 40)) {
    const Mat3 sigma = kGel.cauchy(F);
    const Mat3 pushed = kGel.first_piola(F) * F.transpose() / F.determinant();
    EXPECT_LE((sigma - pushed).norm(), 1e-12 * std::max(sigma.norm(), kGel.mu)) << "F =\n" << F;
    EXPECT_LE((sigma - sigma.transpose()).norm(), 1e-12 * std::max(sigma.norm(), kGel.mu));
  }
}

// W(Q F) = W(F) and P(Q F) = Q P(F) for rotations Q.
TEST(NeoHookean, Objectivity) {
  Rng rng(703);
  double worst_energy = 0.0, worst_stress = 0.0;
  for (const Mat3& F : sample_deformations(rng, 50)) {
    const Mat3 Q = testing::random_rotation(rng);
    const double W = kGel.energy(F);
    const Mat3 P = kGel.first_piola(F);
    const double energy_error = std::abs(kGel.energy(Q * F) - W) / std::max(std::abs(W), kGel.mu);
    const double stress_error = (kGel.first_piola(Q * F) - Q * P).norm() / std::max(P.norm(), kGel.mu);
    worst_energy = std::max(worst_energy, energy_error);
    worst_stress = std::max(worst_stress, stress_error);
    EXPECT_LE(energy_error, 1e-12);
    EXPECT_LE(stress_error, 1e-12);
  }
  std::printf("neo-Hookean objectivity: energy %.2e, P %.2e (relative)\n", worst_energy, worst_stress);
}

TEST(NeoHookean, SmallStrainModuli) {
  const double e = 1e-7;
  // Simple shear: sigma_12 = mu gamma; pure dilation: pressure = -K dV/V, K = lambda + 2 mu / 3.
  Mat3 shear = Mat3::Identity();
  shear(0, 1) = e;
  EXPECT_NEAR(kGel.cauchy(shear)(0, 1) / e, kGel.mu, 1e-6 * kGel.mu);
  const Mat3 dilation = (1.0 + e) * Mat3::Identity();
  const double bulk = kGel.lambda + 2.0 * kGel.mu / 3.0;
  EXPECT_NEAR(kGel.bulk_modulus(), bulk, 1e-12 * bulk);
  EXPECT_NEAR(kGel.cauchy(dilation).trace() / 3.0 / (3.0 * e), bulk, 1e-6 * bulk);
  EXPECT_EQ(kGel.shear_modulus(), kGel.mu);
}

// validate() names the parameter and its value.
void expect_rejected(const NeoHookean& m, const std::string& expected) {
  try {
    m.validate();
    ADD_FAILURE() << "accepted mu = " << m.mu << ", lambda = " << m.lambda;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("neo_hookean"), std::string::npos) << e.what();
  }
}

TEST(NeoHookean, ValidationNamesTheBadParameter) {
  EXPECT_NO_THROW(kGel.validate());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  expect_rejected(NeoHookean{0.0, 1.0}, "mu = 0 must be > 0");
  expect_rejected(NeoHookean{-1.0, 1.0}, "mu = -1 must be > 0");
  expect_rejected(NeoHookean{1.0, 0.0}, "lambda = 0 must be > 0");
  expect_rejected(NeoHookean{1.0, -2.0}, "lambda = -2 must be > 0");
  expect_rejected(NeoHookean{nan, 1.0}, "mu = nan is not a finite number");
  expect_rejected(NeoHookean{1.0, inf}, "lambda = inf is not a finite number");
}

}  // namespace
}  // namespace rkpm::materials
