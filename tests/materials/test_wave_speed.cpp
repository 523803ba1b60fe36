// Wave-speed bounds for the stable time step: exact P-wave speed at F = I, and
// never below the numerical acoustic tensor's largest eigenvalue over many
// random propagation directions and deformations.
#include "lce_fixtures.hpp"
#include "rkpm/materials/mooney_rivlin.hpp"
#include "support/finite_differences.hpp"
#include "support/random_tensors.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rkpm::materials {
namespace {

using testing::Rng;

constexpr double kDensity = 1.0e3;

// sqrt(max over N of lambda_max(Q(N)) / rho0), Q from differences of P.
template <class Stress>
double numerical_wave_speed(const Stress& first_piola, const Mat3& F, Rng& rng, int directions) {
  double largest = 0.0;
  for (int i = 0; i < directions + 3; ++i) {
    const Vec3 N = i < 3 ? Vec3(Vec3::Unit(i)) : testing::random_unit_vector(rng);
    largest = std::max(largest, testing::largest_eigenvalue_symmetrised(testing::acoustic_tensor(first_piola, F, N, 1e-4)));
  }
  return std::sqrt(largest / kDensity);
}

TEST(WaveSpeed, MooneyRivlinAtIdentityIsThePWaveSpeed) {
  const MooneyRivlin m{2.126e3, 1.7e2, 1.7e5};
  const double p_wave = std::sqrt((m.bulk_modulus() + 4.0 / 3.0 * m.shear_modulus()) / kDensity);
  Rng rng(401);
  const double numeric = numerical_wave_speed([&](const Mat3& F) { return m.first_piola(F); }, Mat3::Identity(), rng, 50);
  std::printf("MR at F = I: bound %.6f, P-wave %.6f, numerical %.6f m/s\n", m.wave_speed(Mat3::Identity(), kDensity),
              p_wave, numeric);
  EXPECT_NEAR(m.wave_speed(Mat3::Identity(), kDensity), p_wave, 1e-10 * p_wave);
  EXPECT_NEAR(numeric, p_wave, 1e-6 * p_wave);
}

TEST(WaveSpeed, MooneyRivlinBoundIsConservative) {
  Rng rng(402);
  for (const MooneyRivlin m : {MooneyRivlin{1.3, 0.7, 5.0}, MooneyRivlin{2.126e3, 1.7e2, 1.7e5}, MooneyRivlin{1.0, -0.3, 2.0}}) {
    double lowest = 1e300, highest = 0.0;
    for (int i = 0; i < 60; ++i) {
      const Mat3 F = testing::random_deformation(rng, 0.3, 3.0, 1.0);
      const double bound = m.wave_speed(F, kDensity);
      const double numeric = numerical_wave_speed([&](const Mat3& G) { return m.first_piola(G); }, F, rng, 200);
      lowest = std::min(lowest, bound / numeric);
      highest = std::max(highest, bound / numeric);
      EXPECT_GE(bound, numeric * (1.0 - 1e-7)) << "F =\n" << F;
    }
    std::printf("MR (c1 %.3g, c2 %.3g, lambda %.3g): bound / numerical wave speed in [%.4f, %.4f]\n", m.c1, m.c2,
                m.lambda, lowest, highest);
  }
}

TEST(WaveSpeed, LceAtIdentityIsThePWaveSpeed) {
  for (const double K_over_mu : {20.0, 1e4}) {
    auto m = testing::dimensionless_lce(2.0);
    m.mu = 1.0e4;
    m.K = K_over_mu * m.mu;
    const DirectorPoint d{Vec3::UnitZ(), Vec3::UnitZ(), Mat3::Zero()};
    // Small-strain bulk modulus K + 2 mu / 3, so the P-wave modulus is K + 2 mu.
    const double bulk = m.K + 2.0 / 3.0 * m.mu;
    const double p_wave = std::sqrt((bulk + 4.0 / 3.0 * m.mu) / kDensity);
    const double bound = m.wave_speed(Mat3::Identity(), d, kDensity);
    Rng rng(403);
    const double numeric = numerical_wave_speed([&](const Mat3& F) { return m.first_piola_passive(F, d); },
                                                Mat3::Identity(), rng, 200);
    std::printf("LCE at F = I, K = %.0e mu, s = 2: bound %.5f, P-wave %.5f, numerical %.5f m/s (bound/P-wave - 1 = %.2e)\n",
                K_over_mu, bound, p_wave, numeric, bound / p_wave - 1.0);
    // The anisotropy couples oblique directions: the exact maximum lies a
    // little above the P-wave speed, and the bound at most
    // (s - 1) mu / (2 (K + 2 mu)) above it (2.3 % for K = 20 mu).
    EXPECT_GE(numeric, p_wave * (1.0 - 1e-9));
    EXPECT_GE(bound, numeric * (1.0 - 1e-9));
    EXPECT_LE(bound / p_wave - 1.0, (m.s - 1.0) * m.mu / (2.0 * (m.K + 2.0 * m.mu)) + 1e-12);
  }
}

TEST(WaveSpeed, LceBoundIsConservative) {
  Rng rng(404);
  for (const double s : {2.0, 0.5, 5.0}) {
    auto m = testing::dimensionless_lce(s);
    double lowest = 1e300, highest = 0.0;
    for (int i = 0; i < 60; ++i) {
      const Mat3 F = testing::random_deformation(rng, 0.3, 3.0, 1.0);
      const DirectorPoint d{testing::random_unit_vector(rng), testing::random_unit_vector(rng),
                            testing::random_gradient(rng, 1.0)};
      const double bound = m.wave_speed(F, d, kDensity);
      const double numeric =
          numerical_wave_speed([&](const Mat3& G) { return m.first_piola_passive(G, d); }, F, rng, 200);
      lowest = std::min(lowest, bound / numeric);
      highest = std::max(highest, bound / numeric);
      EXPECT_GE(bound, numeric * (1.0 - 1e-7)) << "s = " << s << " F =\n" << F;
    }
    std::printf("LCE s = %.1f (K = 3 mu, with Frank): bound / numerical wave speed in [%.4f, %.4f]\n", s, lowest, highest);
  }
}

}  // namespace
}  // namespace rkpm::materials
