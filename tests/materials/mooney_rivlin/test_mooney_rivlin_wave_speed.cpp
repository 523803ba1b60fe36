// Mooney-Rivlin wave-speed bound for the stable time step: exact P-wave speed at
// F = I, and never below the numerical acoustic tensor's largest eigenvalue over
// many random propagation directions and deformations.
#include "materials/mooney_rivlin/mooney_rivlin.hpp"
#include "support/numerical_wave_speed.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rkpm::materials {
namespace {

using testing::Rng;

constexpr double kDensity = 1.0e3;

TEST(WaveSpeed, MooneyRivlinAtIdentityIsThePWaveSpeed) {
  const MooneyRivlin m{2.126e3, 1.7e2, 1.7e5};
  const double p_wave = std::sqrt((m.bulk_modulus() + 4.0 / 3.0 * m.shear_modulus()) / kDensity);
  Rng rng(401);
  const double numeric = testing::numerical_wave_speed([&](const Mat3& F) { return m.first_piola(F); }, Mat3::Identity(), rng, 50, kDensity);
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
      const double numeric = testing::numerical_wave_speed([&](const Mat3& G) { return m.first_piola(G); }, F, rng, 200, kDensity);
      lowest = std::min(lowest, bound / numeric);
      highest = std::max(highest, bound / numeric);
      EXPECT_GE(bound, numeric * (1.0 - 1e-7)) << "F =\n" << F;
    }
    std::printf("MR (c1 %.3g, c2 %.3g, lambda %.3g): bound / numerical wave speed in [%.4f, %.4f]\n", m.c1, m.c2,
                m.lambda, lowest, highest);
  }
}

}  // namespace
}  // namespace rkpm::materials
