// LCE wave-speed bound for the stable time step: within a known margin of the
// P-wave speed at F = I, and never below the numerical acoustic tensor's largest
// eigenvalue over many random propagation directions, deformations and directors.
#include "lce_fixtures.hpp"
#include "support/numerical_wave_speed.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rkpm::materials {
namespace {

using testing::Rng;

constexpr double kDensity = 1.0e3;

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
    const double numeric = testing::numerical_wave_speed([&](const Mat3& F) { return m.first_piola_passive(F, d); },
                                                Mat3::Identity(), rng, 200, kDensity);
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
          testing::numerical_wave_speed([&](const Mat3& G) { return m.first_piola_passive(G, d); }, F, rng, 200, kDensity);
      lowest = std::min(lowest, bound / numeric);
      highest = std::max(highest, bound / numeric);
      EXPECT_GE(bound, numeric * (1.0 - 1e-7)) << "s = " << s << " F =\n" << F;
    }
    std::printf("LCE s = %.1f (K = 3 mu, with Frank): bound / numerical wave speed in [%.4f, %.4f]\n", s, lowest, highest);
  }
}

}  // namespace
}  // namespace rkpm::materials
