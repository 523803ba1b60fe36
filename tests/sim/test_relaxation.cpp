// Static equilibrium by relaxation. A Mooney-Rivlin block on rollers (x fixed on
// xmin, y on ymin, z on zmin) is pulled by a follower tension on xmax: the exact
// equilibrium is the homogeneous uniaxial state, Cauchy sigma_11 = -p, sigma_22 =
// sigma_33 = 0, which the linear RK basis and the SCNI cells reproduce exactly, so
// the relaxed field must match it to the tolerance of the relaxation.
#include "sim_fixtures.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstdio>

namespace rkpm::sim {
namespace {

constexpr double kC1 = 400.0, kC2 = 100.0, kLambda = 2000.0;  // mu = 1000 Pa, K = 8000 Pa
constexpr double kTension = 300.0;                             // Pa, pressure = -kTension

const std::string kPulledBlock = R"([scene]
name = "pulled"
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
[body.material]
model = "mooney_rivlin"
c1 = 400
c2 = 100
lambda = 2000
[[body.boundary]]
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
surface = "xmax"
pressure = -300
)";

// Cauchy stress of the modified Mooney-Rivlin solid for F = diag(l, t, t), written
// out from VERIFICATION section 2 (independent of the material code under test):
// sigma = (2/J) [ (c1 + c2 I1) B - c2 B^2 + (-c1 J^(2/3) - 2 c2 J^(4/3) + 2 lambda ln J) I ].
Eigen::Vector2d uniaxial_cauchy(double l, double t) {
  const double J = l * t * t, b1 = l * l, b2 = t * t, I1 = b1 + 2.0 * b2;
  const double p = -kC1 * std::pow(J, 2.0 / 3.0) - 2.0 * kC2 * std::pow(J, 4.0 / 3.0) + 2.0 * kLambda * std::log(J);
  return (2.0 / J) * Eigen::Vector2d((kC1 + kC2 * I1) * b1 - kC2 * b1 * b1 + p, (kC1 + kC2 * I1) * b2 - kC2 * b2 * b2 + p);
}

// Stretches (l, t) with sigma_11 = tension, sigma_22 = 0, by Newton's method.
Eigen::Vector2d uniaxial_stretches(double tension) {
  Eigen::Vector2d s(1.0, 1.0);
  for (int it = 0; it < 50; ++it) {
    const Eigen::Vector2d r = uniaxial_cauchy(s[0], s[1]) - Eigen::Vector2d(tension, 0.0);
    Eigen::Matrix2d jac;
    const double h = 1e-7;
    for (int k = 0; k < 2; ++k) {
      Eigen::Vector2d sp = s;
      sp[k] += h;
      jac.col(k) = (uniaxial_cauchy(sp[0], sp[1]) - uniaxial_cauchy(s[0], s[1])) / h;
    }
    s -= jac.lu().solve(r);
    if (r.norm() < 1e-12 * tension) break;
  }
  return s;
}

struct Relaxed {
  std::int64_t steps = 0;
  bool converged = false;
  double displacement_error = 0.0;  // max |u - u_exact| / max |u_exact|
  double residual = 0.0;
};

// Steps the pulled block until the relaxation criterion holds (in both modes) and
// compares the physical displacement with the homogeneous solution.
Relaxed relax_pulled_block(const std::string& mode, double damping, std::int64_t max_steps) {
  auto sw = testing::build_from_text(testing::with(testing::with(kPulledBlock, "mode", mode), "damping",
                                                   std::to_string(damping)));
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  Relaxed r;
  while (sw.world->step < max_steps && !(r.converged = integrator.converged())) {integrator.step();
    if (getenv("DBG") && sw.world->step % 20 == 0) std::printf("step %lld res %g ke %g dt %g\n", (long long)sw.world->step, integrator.residual(), integrator.kinetic_measure(), integrator.dt());}
  r.steps = sw.world->step;
  r.residual = integrator.residual();

  const Eigen::Vector2d lt = uniaxial_stretches(kTension);
  const Body& body = *sw.world->bodies.front();
  std::vector<Vec3> u;
  physical_displacement(body, u);
  double err = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < body.size(); ++i) {
    const Vec3& X = body.cloud.X[i];  // the rollers are at the origin planes
    const Vec3 exact((lt[0] - 1.0) * X.x(), (lt[1] - 1.0) * X.y(), (lt[1] - 1.0) * X.z());
    err = std::max(err, (u[i] - exact).norm());
    if (getenv("DBG")) std::printf("X %g %g %g u %g %g %g exact %g %g %g\n", X.x(), X.y(), X.z(), u[i].x(), u[i].y(), u[i].z(), exact.x(), exact.y(), exact.z());
    scale = std::max(scale, exact.norm());
  }
  r.displacement_error = err / scale;
  return r;
}

TEST(Relaxation, FireReachesTheHomogeneousUniaxialEquilibrium) {
  testing::ScopedThreads one(1);
  const Eigen::Vector2d lt = uniaxial_stretches(kTension);
  // The closed form of VERIFICATION section 2 as a check of the Newton solution.
  const double J = lt[0] * lt[1] * lt[1];
  EXPECT_NEAR((2.0 / J) * (lt[0] * lt[0] - lt[1] * lt[1]) * (kC1 + kC2 * lt[1] * lt[1]), kTension, 1e-9 * kTension);
  const Relaxed r = relax_pulled_block("relax", 0.0, 200000);
  std::printf("uniaxial tension %.0f Pa: stretch %.6f, lateral %.6f; FIRE: %lld steps, residual %.2e, max relative "
              "displacement error %.3e\n",
              kTension, lt[0], lt[1], static_cast<long long>(r.steps), r.residual, r.displacement_error);
  ASSERT_TRUE(r.converged);
  EXPECT_LE(r.displacement_error, 1e-3);
}

}  // namespace
}  // namespace rkpm::sim
