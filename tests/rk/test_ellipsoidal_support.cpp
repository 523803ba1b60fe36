// Ellipsoidal supports (RKSettings::shape = Ellipsoid, rk/rk_approximation.hpp): on a
// regular lattice they are the balls of the spherical supports; in a thin wall they
// follow the spacing across and along it, so the rows of the gradient operator keep
// their length when the wall is refined in its plane; the reproducing conditions and
// the SCNI patch test hold as for balls, and the kernel gradient is the derivative of
// the kernel.
#include "clouds.hpp"
#include "rkpm/rk/nodal_integration.hpp"
#include "rkpm/rk/rk_approximation.hpp"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <iostream>

using namespace rkpm;
using namespace rkpm::rk;

namespace {

RKSettings ellipsoid(double support = 2.0) {
  RKSettings s;
  s.shape = SupportShape::Ellipsoid;
  s.support = support;
  return s;
}

// A thick shell whose layer spacing (0.6 um) is finer than its in-plane spacing at
// face_cells = 8 and coarser at 24: the case where a ball's size is set by the wrong
// direction.
particles::Cloud thick_shell(int face_cells) {
  particles::ShellSpec spec;
  spec.semi_axes = Vec3(5e-6, 5e-6, 5e-6);
  spec.thickness = 1.2e-6;
  spec.layers = 3;
  spec.face_cells = face_cells;
  return particles::make_shell(spec);
}

double mean_row_length(const GradientOperator& op) {
  return static_cast<double>(op.col.size()) / static_cast<double>(op.n_rows());
}

}  // namespace

TEST(EllipsoidalSupport, IsTheBallOnARegularLattice) {
  const auto cloud = test::jittered_block(5, 0.0);
  const auto supports = ellipsoidal_supports(cloud, 2.0);
  const RKApproximation ball(cloud, RKSettings{}), ell(cloud, ellipsoid());
  ShapeValues a, b;
  double worst = 0.0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    // The block's spacings differ per axis (1/5, 0.8/5, 0.6/5); the ball takes the longest.
    EXPECT_NEAR(supports.radius[i], ball.support_radius()[i], 1e-12) << "particle " << i;
    const Vec3 x = cloud.X[i] + Vec3(0.013, -0.021, 0.007);
    ASSERT_TRUE(ell.evaluate(x, b, true));
    ASSERT_TRUE(ball.evaluate(x, a, true));
    EXPECT_LE(b.ids.size(), a.ids.size());  // shorter in the directions of shorter spacing
  }
  // A cubic lattice (equal spacings) gives the ball exactly, in any orientation of its edges.
  particles::BlockSpec cube;
  cube.size = particles::Vec3(1.0, 1.0, 1.0);
  cube.cells = {4, 4, 4};
  const auto lattice = particles::make_block(cube);
  const auto cubic = ellipsoidal_supports(lattice, 2.0);
  for (std::size_t i = 0; i < lattice.size(); ++i) {
    worst = std::max(worst, (cubic.metric[i] - Mat3::Identity() / (0.5 * 0.5)).norm() * 0.25);
    EXPECT_NEAR(cubic.radius[i], 0.5, 1e-12);
  }
  EXPECT_LE(worst, 1e-12);
  const RKApproximation ball_c(lattice, RKSettings{}), ell_c(lattice, ellipsoid());
  double diff = 0.0;
  for (std::size_t i = 0; i < lattice.size(); ++i) {
    const Vec3 x = lattice.X[i] + Vec3(0.031, 0.017, -0.011);
    ASSERT_TRUE(ball_c.evaluate(x, a, true));
    ASSERT_TRUE(ell_c.evaluate(x, b, true));
    ASSERT_EQ(a.ids, b.ids);
    for (std::size_t k = 0; k < a.ids.size(); ++k)
      diff = std::max({diff, std::abs(a.psi[k] - b.psi[k]), (a.grad[k] - b.grad[k]).norm() * 0.25});
  }
  EXPECT_LE(diff, 1e-12);
}

TEST(EllipsoidalSupport, FollowsTheWallSpacingInEachDirection) {
  const auto cloud = thick_shell(24);
  const auto supports = ellipsoidal_supports(cloud, 2.0);
  // A particle of the middle layer: semi-axes 2 x 0.6 um across the wall and about
  // 2 x the in-plane edge along it.
  const std::size_t i = cloud.size() / 2;
  ASSERT_EQ(cloud.boundary_index[i], -1) << "expected a particle of the middle layer";
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(supports.metric[i]);
  // Semi-axes 1 / sqrt(lambda), longest first: across the wall (its spacing is the
  // longer one here), then the two in-plane directions.
  const Vec3 axes = eig.eigenvalues().cwiseSqrt().cwiseInverse();
  std::cout << "middle-layer particle " << i << ": semi-axes " << axes.transpose() << " m\n";
  const Vec3 across_direction = eig.eigenvectors().col(0);
  const Vec3 radial = (cloud.X[i] - Vec3::Zero()).normalized();
  EXPECT_GT(std::abs(across_direction.dot(radial)), 0.95);
  EXPECT_NEAR(axes(0), 2.0 * 0.6e-6, 0.05 * 1.2e-6);
  const double in_plane = 2.0 * M_PI * 4.4e-6 / (4 * 24);  // the cubed sphere's mean edge at mid-wall
  for (int k = 1; k < 3; ++k) {
    EXPECT_GT(axes(k), 2.0 * 0.7 * in_plane);
    EXPECT_LT(axes(k), 2.0 * 1.3 * in_plane);
  }
  EXPECT_NEAR(supports.radius[i], axes(0), 1e-12 * axes(0));
}

TEST(EllipsoidalSupport, ReproducesLinearFieldsAndGradientsOnAThinWall) {
  const auto cloud = test::default_shell();
  const RKApproximation rk(cloud, ellipsoid());
  ShapeValues sv;
  double unity = 0, linear = 0, grad_linear = 0;
  for (std::size_t i = 0; i < cloud.size(); i += 13) {
    const Vec3 x = 0.5 * (cloud.X[i] + cloud.X[(i + 1) % cloud.size()]);
    if ((cloud.X[i] - cloud.X[(i + 1) % cloud.size()]).norm() > 2.0 * rk.support_radius()[i]) continue;
    rk.evaluate_or_throw(x, sv, true, "test point");
    double pu = 0;
    Vec3 lin = Vec3::Zero();
    Mat3 glin = Mat3::Zero();
    for (std::size_t k = 0; k < sv.ids.size(); ++k) {
      const Vec3& XI = cloud.X[static_cast<std::size_t>(sv.ids[k])];
      pu += sv.psi[k];
      lin += sv.psi[k] * XI;
      glin += XI * sv.grad[k].transpose();
    }
    unity = std::max(unity, std::abs(pu - 1.0));
    linear = std::max(linear, (lin - x).norm() / 10e-6);
    grad_linear = std::max(grad_linear, (glin - Mat3::Identity()).norm());
  }
  EXPECT_LE(unity, 1e-12);
  EXPECT_LE(linear, 1e-12);
  EXPECT_LE(grad_linear, 1e-10);
}

TEST(EllipsoidalSupport, KernelGradientIsTheDerivativeOfTheShapeFunctions) {
  const auto cloud = thick_shell(8);
  const RKApproximation rk(cloud, ellipsoid());
  ShapeValues at, plus, minus;
  const Vec3 x = cloud.X[cloud.size() / 2] + Vec3(0.11e-6, -0.07e-6, 0.05e-6);
  rk.evaluate_or_throw(x, at, true, "centre");
  const double h = 1e-10;  // 1e-4 of the support: central differences to ~1e-8 relative
  double worst = 0.0, scale = 0.0;
  for (int j = 0; j < 3; ++j) {
    const Vec3 e = Vec3::Unit(j) * h;
    rk.evaluate_or_throw(x + e, plus, false, "x+h");
    rk.evaluate_or_throw(x - e, minus, false, "x-h");
    ASSERT_EQ(plus.ids, at.ids);
    ASSERT_EQ(minus.ids, at.ids);
    for (std::size_t k = 0; k < at.ids.size(); ++k) {
      const double fd = (plus.psi[k] - minus.psi[k]) / (2.0 * h);
      worst = std::max(worst, std::abs(fd - at.grad[k](j)));
      scale = std::max(scale, std::abs(at.grad[k](j)));
    }
  }
  EXPECT_LE(worst, 1e-6 * scale) << "largest gradient " << scale;
}

TEST(EllipsoidalSupport, RowsKeepTheirLengthWhenTheWallIsRefinedInItsPlane) {
  const auto coarse = thick_shell(8), fine = thick_shell(24);
  const RKApproximation ball_c(coarse, RKSettings{}), ball_f(fine, RKSettings{});
  const RKApproximation ell_c(coarse, ellipsoid()), ell_f(fine, ellipsoid());
  const double ball_growth = mean_row_length(build_gradient_operator(fine, ball_f, Integration::SCNI)) /
                             mean_row_length(build_gradient_operator(coarse, ball_c, Integration::SCNI));
  const auto op_f = build_gradient_operator(fine, ell_f, Integration::SCNI);
  const double ell_growth =
      mean_row_length(op_f) / mean_row_length(build_gradient_operator(coarse, ell_c, Integration::SCNI));
  std::cout << "mean row length, face_cells 8 -> 24: ball x" << ball_growth << ", ellipsoid x" << ell_growth
            << " (ellipsoid at 24: " << mean_row_length(op_f) << ")\n";
  EXPECT_GT(ball_growth, 1.5);
  EXPECT_LT(ell_growth, 1.15);

  // The SCNI patch test on the refined wall: a linear field's smoothed gradient is exact.
  Mat3 A;
  A << 1.1, 0.2, -0.1, 0.05, 0.9, 0.3, -0.2, 0.1, 1.05;
  const Vec3 c(1e-6, -2e-6, 0.5e-6);
  std::vector<Vec3> x(fine.size());
  for (std::size_t i = 0; i < fine.size(); ++i) x[i] = A * fine.X[i] + c;
  std::vector<Mat3> F;
  deformation_gradients(op_f, x, F);
  double worst = 0.0;
  for (const auto& FL : F) worst = std::max(worst, (FL - A).norm());
  EXPECT_LE(worst, 1e-10);
}
