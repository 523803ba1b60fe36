// Stabilized conforming nodal integration (VERIFICATION section 1): the integration
// constraint, the linear patch test and free-body stability, on every generated cloud,
// with direct nodal integration as the contrast.
#include "clouds.hpp"
#include "rkpm/rk/nodal_integration.hpp"
#include "rkpm/rk/stabilization.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <iostream>
#include <set>

using namespace rkpm;
using namespace rkpm::rk;

namespace {

struct Patch {
  double constraint = 0;      // integration constraint, relative
  double gradient = 0;        // max |F_L - (I + A)|
  double interior_force = 0;  // max |f_I| over interior particles, relative
  double total_residual = 0;  // max |f_int - f_ext| over all particles, relative
  double stabilization_force = 0;  // max |f_stab| for the linear field, relative
};

// `boundary_rule` is the boundary quadrature's rule, the gradient operator's by default.
Patch patch_test(const particles::Cloud& cloud, Integration scheme,
                 GradientPrecision precision = GradientPrecision::Double, FacetRule rule = FacetRule::Corners,
                 std::optional<FacetRule> boundary_rule = std::nullopt) {
  const RKApproximation rk(cloud, RKSettings{});
  const auto op = build_gradient_operator(cloud, rk, scheme, precision, {}, rule);
  const auto bq = build_boundary_quadrature(cloud, rk, 0u, boundary_rule.value_or(rule));
  const auto n = cloud.size();
  Patch p;

  // Integration constraint: sum_L V_L b_I(X_L) = sum_boundary Psi_I(x_f) A_f.
  std::vector<Vec3> lhs(n, Vec3::Zero()), rhs(n, Vec3::Zero());
  double scale = 0;
  for (Index L = 0; L < op.n_rows(); ++L)
    for_each_acting_entry(op, L, [&](Index I, const Vec3& b) {
      lhs[I] += op.weight[L] * b;
      scale = std::max(scale, op.weight[L] * b.norm());
    });
  std::vector<char> touches_boundary(n, 0);
  for (std::size_t f = 0; f < bq.point.size(); ++f)
    for (Index k = bq.row_offset[f]; k < bq.row_offset[f + 1]; ++k) {
      rhs[bq.col[k]] += bq.psi[k] * bq.area[f];
      touches_boundary[bq.col[k]] = 1;
    }
  for (std::size_t I = 0; I < n; ++I) p.constraint = std::max(p.constraint, (lhs[I] - rhs[I]).norm() / scale);

  // Linear displacement u = A X + c: exact F at every integration point.
  Mat3 A;
  A << 0.10, -0.03, 0.02, 0.05, -0.08, 0.04, -0.02, 0.07, 0.12;
  // A translation of the order of the body's size (a metre-sized shift of a 5 um cell
  // would only measure the round-off of sum_I b_I times an absurd lever arm).
  Vec3 lo = cloud.X[0], hi = cloud.X[0];
  for (const auto& X : cloud.X) {
    lo = lo.cwiseMin(X);
    hi = hi.cwiseMax(X);
  }
  const Vec3 c = (hi - lo).norm() * Vec3(0.3, -0.1, 0.2);
  std::vector<Vec3> x(n);
  for (std::size_t I = 0; I < n; ++I) x[I] = cloud.X[I] + A * cloud.X[I] + c;
  std::vector<Mat3> F;
  deformation_gradients(op, x, F);
  const Mat3 exact = Mat3::Identity() + A;
  for (const auto& f : F) p.gradient = std::max(p.gradient, (f - exact).norm() / exact.norm());

  // The resulting constant stress: zero force at interior particles; at the others
  // the internal force equals the traction P N integrated on the boundary.
  const Mat3 eps = 0.5 * (A + A.transpose());
  const Mat3 P = 1.3 * eps.trace() * Mat3::Identity() + 2.0 * 0.7 * eps;
  std::vector<Mat3> stress(F.size(), P);
  std::vector<Vec3> f;
  internal_forces(op, stress, f);
  // The stabilization adds nothing for a linear field (its residual vanishes to the
  // interpolation's storage rounding).
  auto stab = build_stabilization(cloud.volume, std::vector<double>(n, 1.0), 0.1);
  std::vector<Vec3> d(n), f_stab(n, Vec3::Zero());
  for (std::size_t I = 0; I < n; ++I) d[I] = x[I] - cloud.X[I];
  add_stabilization_forces(build_nodal_interpolation(cloud, rk), stab, d, f_stab);
  double fscale = 0;
  for (std::size_t I = 0; I < n; ++I) fscale = std::max(fscale, f[I].norm());
  for (std::size_t I = 0; I < n; ++I) p.stabilization_force = std::max(p.stabilization_force, f_stab[I].norm() / fscale);
  for (std::size_t I = 0; I < n; ++I) {
    if (!touches_boundary[I]) p.interior_force = std::max(p.interior_force, f[I].norm() / fscale);
    p.total_residual = std::max(p.total_residual, (f[I] - P * rhs[I]).norm() / fscale);
  }
  return p;
}

// Exact to round-off: 1e-10 with double storage. Single-precision entries carry a
// relative error of 6e-8 each; a row sums ~100 of them and the force at a particle ~100
// rows, so 1e-6 bounds their round-off while a wrong term (e.g. a missing own-particle
// correction or a gather in absolute positions) shows at 1e-3 or more.
void expect_patch(const particles::Cloud& cloud, const char* label,
                  GradientPrecision precision = GradientPrecision::Double, FacetRule rule = FacetRule::Corners) {
  const auto p = patch_test(cloud, Integration::SCNI, precision, rule);
  const bool single = precision == GradientPrecision::Float;
  const double tolerance = single ? 1e-6 : 1e-10;
  std::cout << label << " (SCNI at the facets' " << (rule == FacetRule::Corners ? "corners" : "centroids") << ", "
            << (single ? "float" : "double") << " storage, " << cloud.size()
            << " particles): integration constraint " << p.constraint << ", F error " << p.gradient
            << ", interior force " << p.interior_force << ", residual " << p.total_residual
            << ", stabilization force " << p.stabilization_force << "\n";
  EXPECT_LE(p.constraint, tolerance) << label;
  // The interpolation is stored in float whatever the gradients' precision: a linear
  // field's residual is its rounding (about 1e-7 of the row's reach times the gradient),
  // 3e-10 of the internal force here; a wrong weight (e.g. the own-particle correction
  // left out) leaves a residual of the order of the displacement, 1e-2 or more.
  EXPECT_LE(p.stabilization_force, 1e-8) << label;
  EXPECT_LE(p.gradient, tolerance) << label;
  EXPECT_LE(p.interior_force, tolerance) << label;
  EXPECT_LE(p.total_residual, tolerance) << label;
}

// Dense stiffness of isotropic linear elasticity (lambda = mu = 1) from the operator.
Eigen::MatrixXd stiffness(const GradientOperator& op, std::size_t n) {
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  Eigen::Matrix<double, 6, 6> D = Eigen::Matrix<double, 6, 6>::Zero();
  D.topLeftCorner<3, 3>().setConstant(1.0);
  D.diagonal() << 3, 3, 3, 1, 1, 1;
  for (Index L = 0; L < op.n_rows(); ++L) {
    std::vector<Index> cols;
    std::vector<Vec3> grads;
    for_each_acting_entry(op, L, [&](Index I, const Vec3& b) {
      cols.push_back(I);
      grads.push_back(b);
    });
    const auto m = static_cast<Index>(cols.size());
    Eigen::MatrixXd B = Eigen::MatrixXd::Zero(6, 3 * m);
    for (Index k = 0; k < m; ++k) {
      const Vec3& b = grads[k];
      B(0, 3 * k) = b.x(); B(1, 3 * k + 1) = b.y(); B(2, 3 * k + 2) = b.z();
      B(3, 3 * k) = b.y(); B(3, 3 * k + 1) = b.x();
      B(4, 3 * k + 1) = b.z(); B(4, 3 * k + 2) = b.y();
      B(5, 3 * k) = b.z(); B(5, 3 * k + 2) = b.x();
    }
    const Eigen::MatrixXd KL = op.weight[L] * B.transpose() * D * B;
    for (Index a = 0; a < m; ++a)
      for (Index b = 0; b < m; ++b) K.block<3, 3>(3 * cols[a], 3 * cols[b]) += KL.block<3, 3>(3 * a, 3 * b);
  }
  return K;
}

// The stabilization's stiffness, column by column from the force the simulator uses.
Eigen::MatrixXd stabilization_stiffness(const particles::Cloud& cloud, const RKApproximation& rk, double alpha) {
  const auto n = cloud.size();
  const auto N = build_nodal_interpolation(cloud, rk);
  auto s = build_stabilization(cloud.volume, std::vector<double>(n, 1.0), alpha);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  std::vector<Vec3> d(n, Vec3::Zero()), f(n);
  for (std::size_t j = 0; j < n; ++j)
    for (int a = 0; a < 3; ++a) {
      d[j][a] = 1.0;
      std::fill(f.begin(), f.end(), Vec3::Zero());
      add_stabilization_forces(N, s, d, f);
      for (std::size_t i = 0; i < n; ++i) K.block<3, 1>(3 * i, 3 * j + a) = -f[i];
      d[j][a] = 0.0;
    }
  return K;
}

// Eigenvalues of the free-body stiffness relative to the largest, ascending.
Eigen::VectorXd relative_spectrum(const particles::Cloud& cloud, Integration scheme, double alpha,
                                  GradientPrecision precision = GradientPrecision::Double,
                                  FacetRule rule = FacetRule::Corners) {
  const RKApproximation rk(cloud, RKSettings{});
  const auto op = build_gradient_operator(cloud, rk, scheme, precision, {}, rule);
  Eigen::MatrixXd K = stiffness(op, cloud.size());
  if (alpha > 0.0) K += stabilization_stiffness(cloud, rk, alpha);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(K, Eigen::EigenvaluesOnly);
  return es.eigenvalues() / es.eigenvalues().maxCoeff();
}

int count_below(const Eigen::VectorXd& ev, double threshold) {
  int count = 0;
  for (Eigen::Index i = 0; i < ev.size(); ++i) count += std::abs(ev(i)) < threshold;
  return count;
}

// "Zero" is below 1e-8 of the largest eigenvalue; a mode below 1e-4 is spurious (the
// lowest physical modes of these clouds sit near 1e-2).
void expect_stable(const particles::Cloud& cloud, const char* label) {
  const auto stabilized = relative_spectrum(cloud, Integration::SCNI, 0.1);
  const auto scni = relative_spectrum(cloud, Integration::SCNI, 0.0);
  const auto direct = relative_spectrum(cloud, Integration::Direct, 0.0);
  std::cout << label << " (" << cloud.size() << " particles): eigenvalues below 1e-8 / below 1e-4 / 7th: "
            << "stabilized SCNI " << count_below(stabilized, 1e-8) << " / " << count_below(stabilized, 1e-4) << " / "
            << stabilized(6) << "; plain SCNI " << count_below(scni, 1e-8) << " / " << count_below(scni, 1e-4)
            << " / " << scni(6) << "; direct " << count_below(direct, 1e-8) << " / " << count_below(direct, 1e-4)
            << " / " << direct(6) << "\n";
  EXPECT_EQ(count_below(stabilized, 1e-8), 6) << label;
  EXPECT_EQ(count_below(stabilized, 1e-4), 6) << label;
  EXPECT_GT(stabilized(6), 1e-3) << label;
  // The contrast: without stabilization, nodal integration has spurious low-energy modes.
  EXPECT_GT(count_below(direct, 1e-4), 6) << label;
  EXPECT_GT(count_below(scni, 1e-4), 6) << label;
}

}  // namespace

TEST(PatchTest, JitteredBlock) { expect_patch(test::jittered_block(), "jittered block"); }
TEST(PatchTest, Sphere) { expect_patch(test::small_sphere(), "sphere"); }
TEST(PatchTest, ShellAtDefaultResolution) { expect_patch(test::default_shell(), "RBC shell"); }

TEST(PatchTest, SinglePrecisionStorageIsExactToItsRoundOff) {
  expect_patch(test::jittered_block(), "jittered block", GradientPrecision::Float);
  expect_patch(test::default_shell(), "RBC shell", GradientPrecision::Float);
}

TEST(PatchTest, CentroidRuleOnEveryCloud) {
  expect_patch(test::jittered_block(), "jittered block", GradientPrecision::Double, FacetRule::Centroids);
  expect_patch(test::small_sphere(), "sphere", GradientPrecision::Double, FacetRule::Centroids);
  expect_patch(test::default_shell(), "RBC shell", GradientPrecision::Double, FacetRule::Centroids);
}

// The integration constraint holds only with the same rule on the boundary as in the
// cells: the check above is not blind to the boundary quadrature. Mixing the rules
// leaves F exact (each cell's rule is exact for linear fields) but unbalances the
// boundary particles' forces by the difference of the two rules' boundary integrals.
TEST(PatchTest, TheBoundaryQuadratureMustFollowTheCellRule) {
  for (const auto& [cells, boundary] : {std::pair{FacetRule::Corners, FacetRule::Centroids},
                                       std::pair{FacetRule::Centroids, FacetRule::Corners}}) {
    const auto p = patch_test(test::jittered_block(), Integration::SCNI, GradientPrecision::Double, cells, boundary);
    std::cout << "jittered block, mixed rules: integration constraint " << p.constraint << ", F error " << p.gradient
              << ", residual " << p.total_residual << "\n";
    EXPECT_LE(p.gradient, 1e-10);
    EXPECT_GT(p.constraint, 1e-3);
    EXPECT_GT(p.total_residual, 1e-4);
  }
}

TEST(PatchTest, DirectNodalIntegrationFailsTheIntegrationConstraint) {
  // The contrast: without smoothing, F is exact (linear consistency of grad Psi) but the
  // integration constraint, and so the force balance, is violated.
  const auto p = patch_test(test::jittered_block(), Integration::Direct);
  std::cout << "jittered block (direct): integration constraint " << p.constraint << ", F error " << p.gradient
            << ", residual " << p.total_residual << "\n";
  EXPECT_LE(p.gradient, 1e-10);
  EXPECT_GT(p.constraint, 1e-4);
}

TEST(Stability, FreeJitteredBlockHasExactlySixZeroModes) {
  expect_stable(test::jittered_block(6, 0.2), "small jittered block");
}

TEST(Stability, FreeSphereHasExactlySixZeroModes) { expect_stable(test::small_sphere(6), "small sphere"); }

TEST(Stability, CentroidRuleKeepsExactlySixZeroModes) {
  const auto spectrum =
      relative_spectrum(test::jittered_block(6, 0.2), Integration::SCNI, 0.1, GradientPrecision::Double,
                        FacetRule::Centroids);
  std::cout << "small jittered block, centroid rule: eigenvalues below 1e-8 / below 1e-4 / 7th: "
            << count_below(spectrum, 1e-8) << " / " << count_below(spectrum, 1e-4) << " / " << spectrum(6) << "\n";
  EXPECT_EQ(count_below(spectrum, 1e-8), 6);
  EXPECT_EQ(count_below(spectrum, 1e-4), 6);
  EXPECT_GT(spectrum(6), 1e-3);
}

TEST(Stability, SinglePrecisionStorageKeepsExactlySixZeroModes) {
  const auto cloud = test::jittered_block(6, 0.2);
  const auto spectrum = relative_spectrum(cloud, Integration::SCNI, 0.1, GradientPrecision::Float);
  std::cout << "small jittered block, float storage: eigenvalues below 1e-8 / below 1e-4 / 7th: "
            << count_below(spectrum, 1e-8) << " / " << count_below(spectrum, 1e-4) << " / " << spectrum(6) << "\n";
  EXPECT_EQ(count_below(spectrum, 1e-8), 6);
  EXPECT_EQ(count_below(spectrum, 1e-4), 6);
  EXPECT_GT(spectrum(6), 1e-3);
}

// The step's force is the transpose of its gradient: sum_L M_L : (sum_I v_I (x) b_I(X_L)) =
// sum_I v_I . (sum_L M_L b_I(X_L)) for any v and M, to double round-off, in both storage
// precisions (in single precision only with the own-particle correction of the relative
// form, whose absence shows at the float round-off, 1e-7).
TEST(NodalIntegration, ScatterIsTheTransposeOfTheGatherInBothPrecisions) {
  const auto cloud = test::default_shell();
  const RKApproximation rk(cloud, RKSettings{});
  const auto n = static_cast<Index>(cloud.size());
  std::vector<Vec3> v(cloud.size());
  std::vector<Mat3> M(cloud.size());
  for (Index i = 0; i < n; ++i) {
    v[i] = cloud.X[i] * 1e6 + Vec3(std::sin(i), std::cos(3.0 * i), std::sin(0.7 * i));
    M[i] = Mat3::Identity() * std::cos(0.3 * i) + Mat3::Constant(std::sin(1.7 * i));
  }
  for (auto precision : {GradientPrecision::Double, GradientPrecision::Float}) {
    const auto op = build_gradient_operator(cloud, rk, Integration::SCNI, precision);
    ASSERT_EQ(op.single_precision(), precision == GradientPrecision::Float);
    std::vector<Vec3> scattered(cloud.size(), Vec3::Zero());
    double lhs = 0.0, scale = 0.0;
    for (Index L = 0; L < n; ++L) {
      const Mat3 G = row_gradient(op, v, L);
      lhs += (M[L].array() * G.array()).sum();
      scale += M[L].norm() * G.norm();
      scatter_row(op, L, 1.0, M[L], scattered.data());
    }
    double rhs = 0.0;
    for (Index I = 0; I < n; ++I) rhs += v[I].dot(scattered[I]);
    EXPECT_LE(std::abs(lhs - rhs), 1e-12 * scale) << (op.single_precision() ? "float" : "double");
    // At rest a body's F is the identity exactly, whatever the storage.
    const std::vector<Vec3> rest(cloud.size(), Vec3::Zero());
    if (op.single_precision()) {
      double worst = 0.0;
      for (Index L = 0; L < n; ++L)
        worst = std::max(worst, (deformation_gradient(op, cloud.X, rest, L) - Mat3::Identity()).norm());
      EXPECT_EQ(worst, 0.0);
    }
  }
}

// The values are stored in float; the relative form makes each row a partition of unity
// to double round-off and reproduces a linear field to the float rounding of psi times
// the row's reach (NodalInterpolation).
TEST(NodalInterpolation, ReproducesLinearFieldsAtParticles) {
  const auto cloud = test::small_sphere();
  const RKApproximation rk(cloud, RKSettings{});
  const auto interp = build_nodal_interpolation(cloud, rk);
  std::vector<Vec3> linear(cloud.size()), uniform(cloud.size(), Vec3(1, 2, 3));
  for (std::size_t I = 0; I < cloud.size(); ++I) linear[I] = 2.0 * cloud.X[I] + Vec3(1, 2, 3);
  double worst_linear = 0, worst_uniform = 0, worst_sum = 0;
  for (std::size_t J = 0; J < cloud.size(); ++J) {
    const auto j = static_cast<Index>(J);
    double reach = 0;
    for (Index k = interp.row_offset[j]; k < interp.row_offset[j + 1]; ++k)
      reach = std::max(reach, (cloud.X[interp.col[k]] - cloud.X[J]).norm());
    worst_linear = std::max(worst_linear, (interpolate(interp, linear, j) - linear[J]).norm() / (2.0 * reach));
    worst_uniform = std::max(worst_uniform, (interpolate(interp, uniform, j) - uniform[J]).norm());
    double sum = 0;
    for_each_weight(interp, j, [&](Index, double w) { sum += w; });
    worst_sum = std::max(worst_sum, std::abs(sum - 1.0));
  }
  EXPECT_LE(worst_linear, 1e-6);  // float rounding: about 6e-8 per entry
  EXPECT_EQ(worst_uniform, 0.0);
  EXPECT_LE(worst_sum, 1e-14);
}

TEST(NodalIntegration, ThinShellBeyondTheSupportIsReportedNotNaN) {
  particles::ShellSpec spec;
  spec.face_cells = 8;
  spec.layers = 2;  // one element through the wall
  const auto cloud = particles::make_shell(spec);
  RKSettings s;
  s.support = 0.9;  // the support no longer spans enough particles
  const RKApproximation rk(cloud, s);
  try {
    build_gradient_operator(cloud, rk, Integration::SCNI);
    FAIL() << "expected an ApproximationError";
  } catch (const ApproximationError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("particle"), std::string::npos) << msg;
    EXPECT_NE(msg.find("condition number"), std::string::npos) << msg;
  }
}
