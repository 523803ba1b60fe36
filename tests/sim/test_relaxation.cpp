// Static equilibrium by relaxation, against homogeneous closed-form states of the
// modified Mooney-Rivlin solid (Cauchy stress from VERIFICATION section 2, written
// out here independently of the material code). A homogeneous deformation is a
// linear field, which the linear RK basis and the SCNI cells reproduce exactly, so
// the relaxed discrete field must match the closed form to the relaxation tolerance
// wherever the discrete load is consistent with it.
//
// Two loadings:
//  * equitriaxial tension (pressure on every face) of a block on rollers: the
//    rollers carry no reaction, so the transformation method is exact;
//  * uniaxial tension of a free block pulled on xmin and xmax, no supports at all.
// Rollers that carry a reaction (a block on an xmin roller pulled on xmax) do not
// give the homogeneous state exactly: the reactions of point-collocated constraints
// (the rows of Psi_I(X_J)) cannot represent the boundary-quadrature traction
// sum_f Psi_I(X_f) A_f, a boundary-layer error near the support (3e-3 on this block).
#include "sim_fixtures.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rkpm::sim {
namespace {

constexpr double kC1 = 400.0, kC2 = 100.0, kLambda = 2000.0;  // mu = 1000 Pa, K = 8000 Pa
constexpr double kTension = 300.0;                             // Pa: pressure = -kTension

const std::string kLoadedBlock = R"([scene]
name = "loaded"
[integrator]
mode = "{mode}"
t_end = 1e6
damping = {damping}
relax_force_tol = 1e-7
relax_velocity_tol = 1e-12
max_steps = 200000
[[body]]
name = "block"
density = 1000
[body.cloud]
generator = "block"
size = [1, 0.6, 0.6]
cells = [5, 3, 3]
jitter = 0.1
)";

const std::string kMooneyRivlin = R"([body.material]
model = "mooney_rivlin"
c1 = 400
c2 = 100
lambda = 2000
)";

// The same small-strain shear modulus, through the neo-Hookean path of the material
// catalog (its table, body material and kernel).
constexpr double kMu = 1000.0, kLame = 4000.0;  // Pa: mu, lambda
const std::string kNeoHookean = R"([body.material]
model = "neo_hookean"
mu = 1000
lambda = 4000
)";

const std::string kRollersAndPressureEverywhere = R"([[body.boundary]]
surface = "xmin"
axes = "x"
[[body.boundary]]
surface = "ymin"
axes = "y"
[[body.boundary]]
surface = "zmin"
axes = "z"
[[term]]
type = "surface_pressure"
body = "block"
surface = "all"
pressure = -300
)";

const std::string kPulledAtBothEnds = R"([[term]]
type = "surface_pressure"
body = "block"
surface = "xmin"
pressure = -300
[[term]]
type = "surface_pressure"
body = "block"
surface = "xmax"
pressure = -300
)";

// Cauchy stress components (sigma_11, sigma_22) for F = diag(l, t, t):
// sigma = (2/J) [ (c1 + c2 I1) B - c2 B^2 + (-c1 J^(2/3) - 2 c2 J^(4/3) + 2 lambda ln J) I ].
Eigen::Vector2d principal_cauchy(double l, double t) {
  const double J = l * t * t, b1 = l * l, b2 = t * t, I1 = b1 + 2.0 * b2;
  const double p = -kC1 * std::pow(J, 2.0 / 3.0) - 2.0 * kC2 * std::pow(J, 4.0 / 3.0) + 2.0 * kLambda * std::log(J);
  return (2.0 / J) * Eigen::Vector2d((kC1 + kC2 * I1) * b1 - kC2 * b1 * b1 + p, (kC1 + kC2 * I1) * b2 - kC2 * b2 * b2 + p);
}

// Stretches (l, t) with principal Cauchy stresses (target_11, target_22), by Newton's method.
Eigen::Vector2d stretches_for(const Eigen::Vector2d& target) {
  Eigen::Vector2d s(1.0, 1.0);
  for (int it = 0; it < 50; ++it) {
    const Eigen::Vector2d r = principal_cauchy(s[0], s[1]) - target;
    if (r.norm() < 1e-12 * target.norm()) break;
    Eigen::Matrix2d jac;
    for (int k = 0; k < 2; ++k) {
      Eigen::Vector2d sp = s;
      sp[k] += 1e-7;
      jac.col(k) = (principal_cauchy(sp[0], sp[1]) - principal_cauchy(s[0], s[1])) / 1e-7;
    }
    s -= jac.lu().solve(r);
  }
  return s;
}

struct Relaxed {
  std::int64_t steps = 0;
  bool converged = false;
  double residual = 0.0;
  double displacement_error = 0.0;  // max |u - u_exact| / max |u_exact|
};

// Subtracts from e the infinitesimal rigid motion t + w x (X - Xc) closest to it in the
// least-squares sense: a free body's equilibrium is unique only up to one.
void remove_rigid_motion(const std::vector<Vec3>& X, std::vector<Vec3>& e) {
  Vec3 centre = Vec3::Zero();
  for (const auto& x : X) centre += x / static_cast<double>(X.size());
  Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
  auto basis = [&](std::size_t i) {  // columns: translations, then rotations about x, y, z
    Eigen::Matrix<double, 3, 6> G;
    const Vec3 r = X[i] - centre;
    G << Mat3::Identity(), Vec3::UnitX().cross(r), Vec3::UnitY().cross(r), Vec3::UnitZ().cross(r);
    return G;
  };
  for (std::size_t i = 0; i < X.size(); ++i) {
    const auto G = basis(i);
    normal += G.transpose() * G;
    rhs += G.transpose() * e[i];
  }
  const Eigen::Matrix<double, 6, 1> rigid = normal.ldlt().solve(rhs);
  for (std::size_t i = 0; i < X.size(); ++i) e[i] -= basis(i) * rigid;
}

// Steps until the relaxation criterion holds (checked the same way in both modes) and
// compares the physical displacement with u = (diag(l, t, t) - I) X, up to a rigid
// motion when `free_rigid_motion`.
Relaxed relax(const std::string& loading, const std::string& mode, double damping, const Eigen::Vector2d& lt,
              bool free_rigid_motion, std::int64_t max_steps = 200000, const std::string& material = kMooneyRivlin) {
  auto sw = testing::build_from_text(
      testing::with(testing::with(kLoadedBlock, "mode", mode), "damping", std::to_string(damping)) + material +
      loading);
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  Relaxed r;
  while (sw.world->step < max_steps && !(r.converged = integrator.converged())) integrator.step();
  r.steps = sw.world->step;
  r.residual = integrator.residual();

  const Body& body = *sw.world->bodies.front();
  std::vector<Vec3> u;
  physical_displacement(body, u);
  const Vec3 stretch_minus_one(lt[0] - 1.0, lt[1] - 1.0, lt[1] - 1.0);
  std::vector<Vec3> difference(body.size());
  double scale = 0.0;
  for (std::size_t i = 0; i < body.size(); ++i) {
    const Vec3 exact = stretch_minus_one.cwiseProduct(body.cloud.X[i]);  // the rollers are the planes through 0
    difference[i] = u[i] - exact;
    scale = std::max(scale, exact.norm());
  }
  if (free_rigid_motion) remove_rigid_motion(body.cloud.X, difference);
  double err = 0.0;
  for (const auto& e : difference) err = std::max(err, e.norm());
  r.displacement_error = err / scale;
  return r;
}

TEST(Relaxation, FireReachesTheEquitriaxialEquilibriumOfABlockOnRollers) {
  testing::ScopedThreads one(1);
  const Eigen::Vector2d lt = stretches_for({kTension, kTension});
  EXPECT_NEAR(lt[0], lt[1], 1e-12);
  const Relaxed r = relax(kRollersAndPressureEverywhere, "relax", 0.0, lt, false);
  std::printf("equitriaxial tension %.0f Pa: stretch %.8f; FIRE %lld steps, residual %.2e, max relative "
              "displacement error %.3e\n",
              kTension, lt[0], static_cast<long long>(r.steps), r.residual, r.displacement_error);
  ASSERT_TRUE(r.converged);
  EXPECT_LE(r.displacement_error, 1e-3);
}

TEST(Relaxation, FireReachesTheUniaxialEquilibriumOfABlockPulledAtBothEnds) {
  testing::ScopedThreads one(1);
  const Eigen::Vector2d lt = stretches_for({kTension, 0.0});
  // The closed form sigma_11 = (2/J)(l^2 - t^2)(c1 + c2 t^2) of VERIFICATION section 2.
  const double J = lt[0] * lt[1] * lt[1];
  ASSERT_NEAR((2.0 / J) * (lt[0] * lt[0] - lt[1] * lt[1]) * (kC1 + kC2 * lt[1] * lt[1]), kTension, 1e-9 * kTension);
  const Relaxed r = relax(kPulledAtBothEnds, "relax", 0.0, lt, true);
  std::printf("uniaxial tension %.0f Pa: stretch %.6f, lateral %.6f; FIRE %lld steps, residual %.2e, max relative "
              "displacement error %.3e\n",
              kTension, lt[0], lt[1], static_cast<long long>(r.steps), r.residual, r.displacement_error);
  ASSERT_TRUE(r.converged);
  EXPECT_LE(r.displacement_error, 1e-3)
      << "a pressure on one face of a block must not act on the neighbouring faces: check that boundary-quadrature "
         "facets are tagged with the surfaces of the face they lie on, not with every surface of their owner particle";
}

// Uniaxial tension T of the neo-Hookean block: F = diag(l, t, t) with P_22 = 0, i.e.
// mu (t^2 - 1) + lambda ln J = 0, and sigma_11 = mu (l^2 - t^2) / J = T (sigma_22 = 0),
// written out here from W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2.
Eigen::Vector2d neo_hookean_uniaxial_stretches(double tension) {
  const auto residual = [&](const Eigen::Vector2d& s) {
    const double J = s[0] * s[1] * s[1];
    return Eigen::Vector2d(kMu * (s[0] * s[0] - s[1] * s[1]) / J - tension,
                           kMu * (s[1] * s[1] - 1.0) + kLame * std::log(J));
  };
  Eigen::Vector2d s(1.0, 1.0);
  for (int it = 0; it < 50 && residual(s).norm() > 1e-12 * tension; ++it) {
    Eigen::Matrix2d jac;
    for (int k = 0; k < 2; ++k) {
      Eigen::Vector2d sp = s;
      sp[k] += 1e-7;
      jac.col(k) = (residual(sp) - residual(s)) / 1e-7;
    }
    s -= jac.lu().solve(residual(s));
  }
  return s;
}

TEST(Relaxation, FireReachesTheUniaxialEquilibriumOfANeoHookeanBlock) {
  testing::ScopedThreads one(1);
  const Eigen::Vector2d lt = neo_hookean_uniaxial_stretches(kTension);
  const Relaxed r = relax(kPulledAtBothEnds, "relax", 0.0, lt, true, 200000, kNeoHookean);
  std::printf("neo-Hookean uniaxial tension %.0f Pa: stretch %.6f, lateral %.6f; FIRE %lld steps, residual %.2e, "
              "max relative displacement error %.3e\n",
              kTension, lt[0], lt[1], static_cast<long long>(r.steps), r.residual, r.displacement_error);
  EXPECT_GT(lt[0], 1.05);  // about 10 % strain: beyond linear elasticity
  ASSERT_TRUE(r.converged);
  EXPECT_LE(r.displacement_error, 1e-3);
}

// FIRE against plain mass-proportional damping on the same problem and criterion. The
// best damping for a single mode is critical, c = 2 omega_1; a sweep brackets it.
TEST(Relaxation, FireNeedsFewerStepsThanTheBestViscousDamping) {
  testing::ScopedThreads one(1);
  const Eigen::Vector2d lt = stretches_for({kTension, kTension});
  const Relaxed fire = relax(kRollersAndPressureEverywhere, "relax", 0.0, lt, false);
  std::printf("FIRE: %lld steps\n", static_cast<long long>(fire.steps));
  std::int64_t best = INT64_MAX;
  for (double c : {1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 8.0, 16.0}) {
    const Relaxed viscous = relax(kRollersAndPressureEverywhere, "dynamic", c, lt, false, 20000);
    std::printf("damping c = %5.1f 1/s: %lld steps%s, displacement error %.2e\n", c,
                static_cast<long long>(viscous.steps), viscous.converged ? "" : " (not converged)",
                viscous.displacement_error);
    if (viscous.converged) best = std::min(best, viscous.steps);
  }
  EXPECT_LT(fire.steps, best);
}

// The relaxation criterion's modulus on a graded body. The residual is
// max_I |f_I| / (mu_mean V_I^(2/3)) with mu_mean the volume-weighted mean shear
// modulus, sum_I V_I mu_I / sum_I V_I: a property of the body, not of whichever
// particle comes first. A Mooney-Rivlin block graded 0.5x..4.5x along x and the same
// block graded 4.5x..0.5x are mirror images: the same mean modulus, mirrored forces,
// the same residual; the first particle's modulus (the old scale) differs by 9.
const std::string kGradedBlock = R"([scene]
name = "graded"
[integrator]
mode = "relax"
t_end = 1e6
[[body]]
name = "block"
density = 1000
[body.cloud]
generator = "block"
size = [1, 0.6, 0.6]
cells = [6, 3, 3]
[body.material]
model = "mooney_rivlin"
c1 = 400
c2 = 100
lambda = 2000
grade_axis = "x"
grade_a = {a}
grade_b = {b}
[body.initial]
stretch = [1.05, 0.98, 1.0]
)";

struct GradedResidual {
  double residual = 0.0;       // the integrator's
  double independent = 0.0;    // max_I |f_I| / (mu_mean V_I^(2/3)), mu_mean written out here
  double mu_mean = 0.0;        // written out here
  double mu_first = 0.0;       // the modulus of particle 0
  double old_residual = 0.0;   // max_I |f_I| / (mu_first V_I^(2/3))
};

GradedResidual graded_residual(double a, double b) {
  auto sw = testing::build_from_text(
      testing::with(testing::with(kGradedBlock, "a", std::to_string(a)), "b", std::to_string(b)));
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  const Body& body = *sw.world->bodies.front();
  // The small-strain shear modulus of the modified Mooney-Rivlin solid, 2 (c1 + c2),
  // times the grading factor a s + b, s = (X - X_min) / (X_max - X_min) (Eq. 18).
  double x_min = INFINITY, x_max = -INFINITY;
  for (const auto& X : body.cloud.X) {
    x_min = std::min(x_min, X.x());
    x_max = std::max(x_max, X.x());
  }
  auto mu_at = [&](std::size_t i) { return 2.0 * (kC1 + kC2) * (a * (body.cloud.X[i].x() - x_min) / (x_max - x_min) + b); };
  double weighted = 0.0, volume = 0.0;
  for (std::size_t i = 0; i < body.size(); ++i) {
    EXPECT_NEAR(shear_modulus(body, static_cast<Index>(i)), mu_at(i), 1e-12 * mu_at(i)) << i;
    weighted += body.cloud.volume[i] * mu_at(i);
    volume += body.cloud.volume[i];
  }
  GradedResidual r;
  r.residual = integrator.residual();
  r.mu_mean = weighted / volume;
  r.mu_first = mu_at(0);
  for (std::size_t i = 0; i < body.size(); ++i) {
    const double f = body.force[i].norm() / std::pow(body.cloud.volume[i], 2.0 / 3.0);
    r.independent = std::max(r.independent, f / r.mu_mean);
    r.old_residual = std::max(r.old_residual, f / r.mu_first);
  }
  return r;
}

TEST(Relaxation, ResidualOfAGradedBodyIsScaledByItsMeanShearModulus) {
  testing::ScopedThreads one(1);
  const GradedResidual soft_first = graded_residual(4.0, 0.5), stiff_first = graded_residual(-4.0, 4.5);
  for (const auto* r : {&soft_first, &stiff_first})
    std::printf("mu_mean %.6g Pa, first particle's mu %.6g Pa; residual %.10e (formula %.10e; with the first "
                "particle's mu %.10e)\n",
                r->mu_mean, r->mu_first, r->residual, r->independent, r->old_residual);
  ASSERT_GT(soft_first.residual, 0.0);
  EXPECT_NEAR(soft_first.residual, soft_first.independent, 1e-12 * soft_first.independent);
  EXPECT_NEAR(stiff_first.residual, stiff_first.independent, 1e-12 * stiff_first.independent);
  // Reversing the grading leaves the mean modulus (2.5 x 2 (c1 + c2)) and so the
  // residual unchanged...
  EXPECT_NEAR(soft_first.mu_mean, 2.5 * 2.0 * (kC1 + kC2), 1e-9 * soft_first.mu_mean);
  EXPECT_NEAR(stiff_first.mu_mean, soft_first.mu_mean, 1e-12 * soft_first.mu_mean);
  EXPECT_NEAR(stiff_first.residual, soft_first.residual, 1e-9 * soft_first.residual);
  // ...where the first particle's modulus changes from soft to stiff by the factor 9.
  EXPECT_NEAR(stiff_first.mu_first / soft_first.mu_first, 9.0, 1e-12);
  EXPECT_NEAR(soft_first.old_residual / stiff_first.old_residual, 9.0, 1e-6);
}

}  // namespace
}  // namespace rkpm::sim
