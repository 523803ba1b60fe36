// FIRE (Bitzek et al., PRL 97, 170201, 2006) on its own: point masses whose forces
// the tests set, no mesh and no material. The mixing rule, the growth of the step
// after N_min downhill steps up to dt_max, the stop on an uphill step, and a
// relaxation of an anisotropic quadratic well driven by velocity Verlet + FIRE.
#include "rkpm/sim/fire.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

namespace rkpm::sim {
namespace {

// A world of one body of `n` free point masses (no constraints) at rest.
std::unique_ptr<World> point_masses(std::size_t n, double mass = 1.0) {
  auto world = std::make_unique<World>();
  auto b = std::make_unique<Body>();
  b->name = "points";
  b->cloud.X.assign(n, Vec3::Zero());
  b->mass.assign(n, mass);
  b->inertia = b->mass;
  for (auto* field : {&b->d, &b->v, &b->force}) field->assign(n, Vec3::Zero());
  world->bodies.push_back(std::move(b));
  return world;
}

double norm(const std::vector<Vec3>& v) {
  double s = 0.0;
  for (const auto& x : v) s += x.squaredNorm();
  return std::sqrt(s);
}

double dot(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i].dot(b[i]);
  return s;
}

// The constants of the original FIRE (Bitzek et al. 2006), which Fire uses by default.
const FireParameters kBitzek = FireParameters::bitzek2006();

std::vector<Vec3> random_vectors(std::size_t n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> v(n);
  for (auto& x : v) x = Vec3(u(rng), u(rng), u(rng));
  return v;
}

TEST(Fire, MixingSteersTheVelocityTowardTheForceWithoutLengtheningIt) {
  std::mt19937 rng(7);
  auto world = point_masses(20);
  Body& b = *world->bodies.front();
  b.force = random_vectors(20, rng);
  b.v = random_vectors(20, rng);
  for (std::size_t i = 0; i < 20; ++i) b.v[i] += b.force[i];  // downhill: F . v > 0
  const std::vector<Vec3> v0 = b.v;
  ASSERT_GT(dot(b.force, v0), 0.0);
  const double ke0 = kinetic_energy(*world);

  Fire fire;
  const FireStep r = fire.update(*world, 1e-3, 1.0);

  // v' = (1 - alpha) v + alpha |v| F / |F|, written out here.
  const double alpha = kBitzek.alpha_start, vn = norm(v0), fn = norm(b.force);
  for (std::size_t i = 0; i < 20; ++i) {
    const Vec3 expected = (1.0 - alpha) * v0[i] + alpha * vn * b.force[i] / fn;
    EXPECT_NEAR((b.v[i] - expected).norm(), 0.0, 1e-14 * vn) << i;
  }
  const double cos_before = dot(v0, b.force) / (vn * fn), cos_after = dot(b.v, b.force) / (norm(b.v) * fn);
  std::printf("|v| %.6f -> %.6f; cos(v, F) %.4f -> %.4f; kinetic energy removed %.3e of %.3e\n", vn, norm(b.v),
              cos_before, cos_after, r.dissipated, ke0);
  EXPECT_LE(norm(b.v), vn);
  EXPECT_GT(cos_after, cos_before);
  EXPECT_DOUBLE_EQ(r.dissipated, ke0 - kinetic_energy(*world));
  EXPECT_GE(r.dissipated, 0.0);  // equal masses: |v'| <= |v| is kinetic energy removed
  // The first downhill step changes neither the step nor alpha.
  EXPECT_EQ(r.dt, 1e-3);
  EXPECT_EQ(fire.alpha(), kBitzek.alpha_start);
  EXPECT_EQ(fire.positive_steps(), 1);

  // A velocity parallel to the force keeps its length and direction.
  for (std::size_t i = 0; i < 20; ++i) b.v[i] = 0.3 * b.force[i];
  const std::vector<Vec3> parallel = b.v;
  fire.update(*world, 1e-3, 1.0);
  for (std::size_t i = 0; i < 20; ++i) EXPECT_NEAR((b.v[i] - parallel[i]).norm(), 0.0, 1e-14) << i;
}

TEST(Fire, StepGrowsAndAlphaShrinksAfterNMinDownhillStepsUpToDtMax) {
  auto world = point_masses(3);
  Body& b = *world->bodies.front();
  Fire fire;
  const double dt_max = 2e-3;
  double dt = 1e-3, expected_alpha = kBitzek.alpha_start;
  for (int k = 1; k <= 20; ++k) {
    for (std::size_t i = 0; i < 3; ++i) {  // downhill every time
      b.force[i] = Vec3(1.0, 2.0, static_cast<double>(i));
      b.v[i] = 0.5 * b.force[i];
    }
    const double next = fire.update(*world, dt, dt_max).dt;
    if (k <= kBitzek.n_delay) {
      EXPECT_EQ(next, dt) << "step " << k << ": no growth within the first N_min downhill steps";
    } else {
      EXPECT_EQ(next, std::min(dt * kBitzek.f_inc, dt_max)) << "step " << k;
      expected_alpha *= kBitzek.f_alpha;
    }
    EXPECT_EQ(fire.alpha(), expected_alpha) << "step " << k;
    EXPECT_EQ(fire.positive_steps(), k);
    dt = next;
  }
  std::printf("after 20 downhill steps: dt = %.4g (dt_max %.4g), alpha = %.5f\n", dt, dt_max, fire.alpha());
  EXPECT_EQ(dt, dt_max);  // 1.1^15 > 2: the ceiling is reached and kept
  EXPECT_LT(fire.alpha(), kBitzek.alpha_start);
}

TEST(Fire, UphillStepStopsHalvesTheStepAndResetsAlpha) {
  auto world = point_masses(4, 2.0);
  Body& b = *world->bodies.front();
  Fire fire;
  double dt = 1e-3;
  for (int k = 0; k < 10; ++k) {  // build up some history: alpha below its start
    for (std::size_t i = 0; i < 4; ++i) {
      b.force[i] = Vec3(1.0, 0.0, 0.5 * static_cast<double>(i));
      b.v[i] = b.force[i];
    }
    dt = fire.update(*world, dt, 1.0).dt;
  }
  ASSERT_LT(fire.alpha(), kBitzek.alpha_start);
  ASSERT_EQ(fire.positive_steps(), 10);

  for (std::size_t i = 0; i < 4; ++i) b.v[i] = -0.7 * b.force[i];  // uphill
  const double ke = kinetic_energy(*world);
  const FireStep r = fire.update(*world, dt, 1.0);
  for (const auto& v : b.v) EXPECT_EQ(v, Vec3::Zero());
  EXPECT_EQ(r.dt, kBitzek.f_dec * dt);
  EXPECT_EQ(fire.alpha(), kBitzek.alpha_start);
  EXPECT_EQ(fire.positive_steps(), 0);
  EXPECT_EQ(r.dissipated, ke);  // all of the kinetic energy

  // At rest the power is zero: FIRE treats it as uphill (nothing to mix).
  const FireStep rest = fire.update(*world, r.dt, 1.0);
  EXPECT_EQ(rest.dt, kBitzek.f_dec * r.dt);
  EXPECT_EQ(rest.dissipated, 0.0);
}

// FIRE 2.0's constants (Guenole et al. 2020, LAMMPS's defaults): 20 downhill steps before
// the step grows; on an uphill step after the first 20 steps of the run the step shrinks,
// not below 0.02 dt_max, alpha returns to 0.25, and the velocities are left for the
// caller's half step back; within the first 20 steps the step and alpha are kept.
TEST(Fire2, DelaysTheGrowthStepsBackOnUphillStepsAndKeepsItsStepAtTheStart) {
  const FireParameters p = FireParameters::guenole2020();
  ASSERT_EQ(p.n_delay, 20);
  auto world = point_masses(3);
  Body& b = *world->bodies.front();
  Fire fire(p);
  const double dt_max = 0.1;
  double dt = 0.01;
  for (int k = 1; k <= 25; ++k) {
    for (std::size_t i = 0; i < 3; ++i) b.v[i] = b.force[i] = Vec3(1.0, 0.5, 0.0);
    const double next = fire.update(*world, dt, dt_max).dt;
    EXPECT_EQ(next, k <= 20 ? dt : std::min(dt * p.f_inc, dt_max)) << "downhill step " << k;
    dt = next;
    ++world->step;
  }
  // Uphill inside the initial delay: stopped, but dt and alpha kept.
  const double alpha = fire.alpha();
  world->step = 5;
  for (std::size_t i = 0; i < 3; ++i) b.v[i] = -b.force[i];
  FireStep r = fire.update(*world, dt, dt_max);
  EXPECT_TRUE(r.step_back);
  EXPECT_EQ(r.dt, dt);
  EXPECT_EQ(fire.alpha(), alpha);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(b.v[i], -b.force[i]);  // left for the step back
  // Uphill later: dt shrinks by f_dec, alpha resets, and the floor holds.
  world->step = 100;
  r = fire.update(*world, dt, dt_max);
  EXPECT_EQ(r.dt, p.f_dec * dt);
  EXPECT_EQ(fire.alpha(), p.alpha_start);
  EXPECT_EQ(fire.positive_steps(), 0);
  r = fire.update(*world, 0.021 * dt_max, dt_max);
  EXPECT_DOUBLE_EQ(r.dt, 0.02 * dt_max);
}

// Velocity Verlet + FIRE, as the integrator's relaxation mode does it, on the well
// E = sum_i k_i |x_i|^2 / 2 with stiffnesses spanning a factor 100.
TEST(Fire, RelaxesAnAnisotropicQuadraticWell) {
  constexpr std::size_t n = 10;
  auto world = point_masses(n);
  Body& b = *world->bodies.front();
  std::vector<double> k(n);
  for (std::size_t i = 0; i < n; ++i) {
    k[i] = 1.0 + 99.0 * static_cast<double>(i) / (n - 1);
    b.d[i] = Vec3(1.0, -0.5, 0.25 * static_cast<double>(i));
  }
  const double dt_max = 0.5 * 2.0 / std::sqrt(99.0 + 1.0);  // half the stable step of the stiffest
  auto forces = [&] {
    for (std::size_t i = 0; i < n; ++i) {
      b.force[i] = -k[i] * b.d[i];
    }
  };
  forces();
  const double start = norm(b.d);
  Fire fire;
  double dt = 0.1 * dt_max, largest_dt = dt;
  int steps = 0, stops = 0;
  while (steps < 5000 && (norm(b.d) > 1e-8 * start || norm(b.v) > 1e-8)) {
    for (std::size_t i = 0; i < n; ++i) {
      b.v[i] += 0.5 * dt * acceleration(b, static_cast<Index>(i));
      b.d[i] += dt * b.v[i];
    }
    forces();
    for (std::size_t i = 0; i < n; ++i) b.v[i] += 0.5 * dt * acceleration(b, static_cast<Index>(i));
    const double before = dt;
    dt = fire.update(*world, dt, dt_max).dt;
    if (dt < before) ++stops;
    largest_dt = std::max(largest_dt, dt);
    ++steps;
  }
  std::printf("quadratic well (stiffness 1..100): %d steps, %d uphill stops, largest dt %.4g (dt_max %.4g), |x| %.2e\n",
              steps, stops, largest_dt, dt_max, norm(b.d));
  EXPECT_LT(steps, 5000);
  EXPECT_LE(norm(b.d), 1e-8 * start);
  EXPECT_EQ(largest_dt, dt_max);
  EXPECT_GE(stops, 1);
}

}  // namespace
}  // namespace rkpm::sim
