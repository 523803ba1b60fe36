// Graded Mooney-Rivlin parameters (seed Eq. 18).
#include "materials/mooney_rivlin/graded_parameters.hpp"

#include "support/random_tensors.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <stdexcept>

namespace rkpm::materials {
namespace {

// The seed's substrate: 37.5 um along y, centred at the origin.
GradedMooneyRivlin seed_substrate() {
  GradedMooneyRivlin g;
  g.base = MooneyRivlin{2.126e3, 1.7e2, 1.7e5};
  g.grading.axis = 1;
  g.grading.length = 37.5e-6;
  g.grading.x_min = -0.5 * g.grading.length;
  g.grading.slope = 4.0;
  g.grading.offset = 0.5;
  return g;
}

TEST(GradedParameters, SeedEquation18AtSampledPoints) {
  const GradedMooneyRivlin g = seed_substrate();
  ASSERT_NO_THROW(g.validate());
  const double L0 = g.grading.length;
  testing::Rng rng(7);
  double worst = 0.0;
  for (int i = 0; i < 200; ++i) {
    const Vec3 X(rng.uniform(-L0, L0), rng.uniform(-0.5 * L0, 0.5 * L0), rng.uniform(0, 4.5e-6));
    const double y = X.y() - g.grading.x_min;  // the seed's y, measured from the substrate's edge
    const MooneyRivlin m = g.at(X);
    const double c1 = 2.126 * (4.0 * y / L0 + 0.5) * 1e3;
    const double c2 = 1.7 * (4.0 * y / L0 + 0.5) * 1e2;
    const double lambda = 1.7 * (4.0 * y / L0 + 0.5) * 1e5;
    for (const auto& [got, want] : {std::pair{m.c1, c1}, std::pair{m.c2, c2}, std::pair{m.lambda, lambda}}) {
      worst = std::max(worst, std::abs(got - want) / want);
      EXPECT_NEAR(got, want, 1e-13 * want);
    }
  }
  // Ends of the substrate: factor 0.5 and 4.5 (stiffness ratio 9).
  EXPECT_NEAR(g.at(Vec3(0, g.grading.x_min, 0)).c1, 0.5 * 2.126e3, 1e-12);
  EXPECT_NEAR(g.at(Vec3(0, g.grading.x_min + L0, 0)).lambda, 4.5 * 1.7e5, 1e-9);
  // x and z do not matter when grading along y.
  EXPECT_EQ(g.at(Vec3(1, 0.3e-6, 2)).c2, g.at(Vec3(-5, 0.3e-6, 0)).c2);
  std::printf("Eq. 18 graded parameters: max relative deviation %.2e over 200 points\n", worst);
}

TEST(GradedParameters, RejectsNonPositiveFactorsAndBadGeometry) {
  GradedMooneyRivlin g = seed_substrate();
  EXPECT_THROW(g.at(Vec3(0, g.grading.x_min - 0.2 * g.grading.length, 0)), std::invalid_argument);
  g.grading.length = 0.0;
  EXPECT_THROW(g.validate(), std::invalid_argument);
  g = seed_substrate();
  g.grading.axis = 3;
  EXPECT_THROW(g.validate(), std::invalid_argument);
  g = seed_substrate();
  g.grading.slope = -1.0;  // factor at the far end: -0.5
  EXPECT_THROW(g.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace rkpm::materials
