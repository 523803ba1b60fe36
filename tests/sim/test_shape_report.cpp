// The shape report's fluid gap: the axial distance between the inner surface's top and
// bottom sheets of a shell, on shells whose inner surface is known in closed form,
// and the flag for walls that have passed through each other (which only the
// wall_contact term prevents).
#include "rkpm/particles/generators.hpp"
#include "rkpm/sim/shape_report.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace rkpm::sim {
namespace {

particles::Cloud seed_shell() {
  particles::ShellSpec spec;  // the seed's cell: R x H x T = 5 x 3 x 0.5 um
  spec.face_cells = 16;
  spec.layers = 3;
  return particles::make_shell(spec);
}

// Inner semi-axes 4.5 x 4.5 x 1.0 um: on the axis the fluid is 2.0 um thick and each
// wall 0.5 um. The first bin (r < R/32) holds particles up to r = 0.16 um, where the
// inner sheet sits 1.0 sqrt(1 - (0.16/4.5)^2) = 0.99937 um from the mid-plane, so the
// bin mean is within 1e-3 of the axis value.
TEST(ShapeReport, UndeformedShellHasTheClosedFormGapAndWall) {
  const particles::Cloud cloud = seed_shell();
  const ShapeReport s = measure_shape(cloud, cloud.X, "outer");
  ASSERT_TRUE(s.has_inner_surface);
  EXPECT_NEAR(s.inner_gap_centre, 2.0e-6, 2e-3 * 2.0e-6);
  EXPECT_NEAR(s.wall_thickness_centre, 0.5e-6, 2e-3 * 0.5e-6);
  EXPECT_NEAR(s.h_min, 3.0e-6, 1e-3 * 3.0e-6);
  // The gap narrows toward the rim; the sheets enter while their normal is within 60 deg
  // of the axis, i.e. up to r = 4.46 um, where the gap is still 2 x 0.13 um.
  EXPECT_LT(s.inner_gap_min, 0.5 * s.inner_gap_centre);
  EXPECT_GT(s.inner_gap_min, 0.1e-6);
  EXPECT_FALSE(s.walls_crossed);
  // Mirror-symmetric: the equator's particles, whose normals are horizontal, sit on the
  // fold between the sheets and count in neither (given to one sheet they made the
  // outermost bin look asymmetric).
  EXPECT_LT(s.updown_asymmetry, 1e-12);
  // Every outer bin well inside the inner surface's radius (4.5 of 5 um) sees both inner sheets.
  for (std::size_t k = 0; k < s.r.size(); ++k) {
    if (s.r[k] < 4.0e-6) {
      EXPECT_TRUE(s.inner_in_bin[k]) << "bin at r = " << s.r[k];
    }
  }
}

// The shell mapped onto an Evans-Fung disc of D = 10 um (each vertical line scaled by
// T_EF(r) / h0(r), which is finite up to the rim because both vanish as sqrt(1 - x^2)),
// then each wall pressed toward the mid-plane by a0 exp(-r^2 / (1 um)^2). On the axis
// the inner sheets sit at +-1.0 um * s0, s0 = 0.81 (10 / 7.82) / 3, so the fluid gap is
// 2 s0 um - 2 a0: open for a0 = 0.2 um, crossed for a0 = 0.45 um. Both shapes meet the
// thickness criteria; only the open one is a biconcave cell.
TEST(ShapeReport, WallsPressedThroughEachOtherAreFlaggedAndNotBiconcave) {
  const particles::Cloud cloud = seed_shell();
  const double s0 = 0.81 * (10.0 / 7.82) / 3.0;
  for (const double a0 : {0.2e-6, 0.45e-6}) {
    std::vector<Vec3> x = cloud.X;
    for (auto& p : x) {
      const double r2 = p.x() * p.x() + p.y() * p.y(), x2 = r2 / 25e-12;
      p.z() *= (0.81 + 7.83 * x2 - 4.39 * x2 * x2) * (10.0 / 7.82) / 3.0;
      p.z() -= std::copysign(a0 * std::exp(-r2 / 1e-12), p.z());
    }
    const ShapeReport s = measure_shape(cloud, x, "outer");
    EXPECT_NEAR(s.inner_gap_centre, 2.0e-6 * s0 - 2.0 * a0, 0.02e-6) << "a0 = " << a0;
    EXPECT_NEAR(s.wall_thickness_centre, 0.5e-6 * s0, 0.005e-6) << "a0 = " << a0;
    EXPECT_EQ(s.walls_crossed, a0 > 0.3e-6) << "a0 = " << a0;
    EXPECT_LT(s.h_min / s.h_max, 0.5) << "a0 = " << a0;
    EXPECT_GT(s.r_hmax_over_R, 0.55) << "a0 = " << a0;
    EXPECT_LT(s.r_hmax_over_R, 0.85) << "a0 = " << a0;
    EXPECT_EQ(s.biconcave, !s.walls_crossed) << "a0 = " << a0;
  }
}

// The Evans-Fung disc of the test above (walls not pressed) matches all four criteria of
// the red-blood-cell scene; thickened by 0.6 um everywhere it is still biconcave
// (h_min/h_max (1.04 + 0.6) / (3.3 + 0.6) = 0.42) but 6 % of D off the profile, and
// tilted into a cup (z += 0.4 um (r / R)^2) it is off the up-down criterion.
TEST(ShapeReport, MatchingEvansFungNeedsTheProfileAndTheSymmetryToo) {
  const particles::Cloud cloud = seed_shell();
  const auto disc = [&](double thickening, double cup) {
    std::vector<Vec3> x = cloud.X;
    for (auto& p : x) {
      const double r2 = p.x() * p.x() + p.y() * p.y(), x2 = r2 / 25e-12;
      p.z() *= (0.81 + 7.83 * x2 - 4.39 * x2 * x2) * (10.0 / 7.82) / 3.0;
      p.z() += std::copysign(0.5 * thickening, p.z()) + cup * x2;
    }
    return measure_shape(cloud, x, "outer");
  };
  const ShapeReport evans_fung = disc(0.0, 0.0);
  EXPECT_LT(evans_fung.rms_vs_evans_fung, 0.02);
  EXPECT_TRUE(evans_fung.biconcave);
  EXPECT_TRUE(evans_fung.matches_evans_fung);
  const ShapeReport thick = disc(0.6e-6, 0.0);
  EXPECT_GT(thick.rms_vs_evans_fung, 0.05);
  EXPECT_TRUE(thick.biconcave);
  EXPECT_FALSE(thick.matches_evans_fung);
  const ShapeReport cup = disc(0.0, 0.4e-6);
  EXPECT_GT(cup.updown_asymmetry, 0.05);
  EXPECT_LT(cup.rms_vs_evans_fung, 0.05);
  EXPECT_TRUE(cup.biconcave);
  EXPECT_FALSE(cup.matches_evans_fung);
}

// The same disc with the walls pressed through each other in one place only: a dent of
// depth a0 = 2 um at r = 2.5 um in the direction 22.5 deg (the middle of one of the
// report's eight 45-deg sectors), 0.5 um wide radially and 0.3 rad around. The inner
// sheets there are 0.88 um from the mid-plane; the dent's mean over its sector is
// 0.64 a0 = 1.27 um, over the whole ring 1.27 / 8 um. So the sector's gap is negative,
// the ring's mean gap is not, and the shape counts as crossed.
TEST(ShapeReport, CrossingOnOneSideIsNotAveragedAway) {
  const particles::Cloud cloud = seed_shell();
  std::vector<Vec3> x = cloud.X;
  const double centre_angle = M_PI / 8.0;
  for (auto& p : x) {
    const double r = std::hypot(p.x(), p.y()), x2 = r * r / 25e-12;
    p.z() *= (0.81 + 7.83 * x2 - 4.39 * x2 * x2) * (10.0 / 7.82) / 3.0;
    const double angle = std::remainder(std::atan2(p.y(), p.x()) - centre_angle, 2.0 * M_PI);
    const double dent = 2e-6 * std::exp(-std::pow((r - 2.5e-6) / 0.5e-6, 2) - std::pow(angle / 0.3, 2));
    p.z() -= std::copysign(dent, p.z());
  }
  const ShapeReport s = measure_shape(cloud, x, "outer");
  for (std::size_t k = 0; k < s.r.size(); ++k)
    if (std::abs(s.r[k] - 2.5e-6) < 0.1e-6) {
      ASSERT_TRUE(s.inner_in_bin[k]);
      EXPECT_GT(s.inner_top[k] - s.inner_bottom[k], 0.5e-6) << "bin at r = " << s.r[k];
    }
  EXPECT_LT(s.inner_gap_min, -0.3e-6);
  EXPECT_TRUE(s.walls_crossed);
  EXPECT_NEAR(s.inner_gap_centre, 2.0e-6 * 0.81 * (10.0 / 7.82) / 3.0, 0.01e-6);  // the axis is untouched
}

// A surface without an inner surface (a solid sphere) reports no gap.
TEST(ShapeReport, SolidBodyHasNoInnerSurface) {
  particles::SphereSpec spec;
  spec.cells = 8;
  const particles::Cloud cloud = particles::make_sphere(spec);
  const ShapeReport s = measure_shape(cloud, cloud.X, "surface");
  EXPECT_FALSE(s.has_inner_surface);
  EXPECT_FALSE(s.walls_crossed);
  EXPECT_FALSE(s.has_inner_gap);
  EXPECT_EQ(s.inner_in_bin.size(), s.r.size());
}

}  // namespace
}  // namespace rkpm::sim
