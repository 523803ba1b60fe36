// Neo-Hookean wave speed for the stable time step: the P-wave speed at F = I, never
// below the numerical acoustic tensor's largest eigenvalue, and attained along the
// softest principal direction of C (it is the exact maximum, not a loose bound).
#include "materials/neo_hookean/neo_hookean.hpp"

#include "support/numerical_wave_speed.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rkpm::materials {
namespace {

using testing::Rng;

constexpr double kDensity = 1.0e3;

TEST(NeoHookeanWaveSpeed, AtIdentityIsThePWaveSpeed) {
  for (const NeoHookean m : {NeoHookean{1.5e3, 6.0e3}, NeoHookean{1.0, 1.0e4}}) {
    const double p_wave = std::sqrt((m.lambda + 2.0 * m.mu) / kDensity);
    Rng rng(801);
    const double numeric = testing::numerical_wave_speed([&](const Mat3& F) { return m.first_piola(F); },
                                                         Mat3::Identity(), rng, 50, kDensity);
    EXPECT_NEAR(m.wave_speed(Mat3::Identity(), kDensity), p_wave, 1e-12 * p_wave);
    EXPECT_NEAR(numeric, p_wave, 1e-6 * p_wave);
  }
}

TEST(NeoHookeanWaveSpeed, BoundIsConservativeAndAttained) {
  Rng rng(802);
  for (const NeoHookean m : {NeoHookean{1.5e3, 6.0e3}, NeoHookean{1.0, 0.2}, NeoHookean{1.0, 1.0e3}}) {
    double lowest = 1e300, highest = 0.0;
    for (int i = 0; i < 60; ++i) {
      const Mat3 F = testing::random_deformation(rng, 0.3, 3.0, 1.0);
      const auto P = [&](const Mat3& G) { return m.first_piola(G); };
      const double bound = m.wave_speed(F, kDensity);
      const double numeric = testing::numerical_wave_speed(P, F, rng, 200, kDensity);
      lowest = std::min(lowest, bound / numeric);
      highest = std::max(highest, bound / numeric);
      EXPECT_GE(bound, numeric * (1.0 - 1e-7)) << "F =\n" << F;
      // Along the eigenvector of C's smallest eigenvalue, |F^-T N|^2 = 1 / C_min: the
      // largest eigenvalue of Q(N) there is the bound itself.
      const Eigen::SelfAdjointEigenSolver<Mat3> principal(F.transpose() * F);
      const Vec3 softest = principal.eigenvectors().col(0);
      const double attained =
          std::sqrt(testing::largest_eigenvalue_symmetrised(testing::acoustic_tensor(P, F, softest, 1e-4)) / kDensity);
      EXPECT_NEAR(attained, bound, 1e-6 * bound) << "F =\n" << F;
    }
    std::printf("neo-Hookean (mu %.3g, lambda %.3g): bound / sampled numerical wave speed in [%.4f, %.4f]\n", m.mu,
                m.lambda, lowest, highest);
  }
}

}  // namespace
}  // namespace rkpm::materials
