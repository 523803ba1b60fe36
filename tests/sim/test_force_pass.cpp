// The fused force pass (one sweep over the operator rows: F, Grad h, stress, the
// scattered internal force, Frank divergence and stabilization) equals the unfused
// building blocks of rk/ (a gather for F, a transposed product for the force, the
// stabilization's two products), and its result depends on the thread count only
// through round-off, never on scheduling.
#include "sim_fixtures.hpp"

#include "rkpm/sim/body_state.hpp"

#include "rkpm/rk/stabilization.hpp"

#include <gtest/gtest.h>

#include <iostream>
#include <random>

using namespace rkpm;
using namespace rkpm::sim;
using namespace rkpm::sim::testing;

namespace {

const char* kScene = R"(
[scene]
name = "force_pass"
[integrator]
mode = "dynamic"
t_end = 1e-6
[[body]]
name = "b"
density = 1000.0
[body.cloud]
{cloud}
[body.material]
{material}
)";

const char* kLce = R"(model = "lce"
mu = 1e4
bulk = 1e5
s = 2.0
kappa = 1e-11
zeta = -3e3
[body.director]
initial = "radial"
boundary = "free")";

const char* kMooneyRivlin = R"(model = "mooney_rivlin"
c1 = 2.126e3
c2 = 1.7e2
lambda = 1.7e5)";

// A smooth finite deformation plus a rough perturbation (which the stabilization
// resists), and a perturbed director: every part of the pass is exercised.
void deform(Body& b) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Mat3 A;
  A << 0.08, 0.03, -0.02, 0.01, -0.05, 0.04, 0.02, 0.0, 0.06;
  const double h = std::cbrt(b.cloud.volume[0]);
  for (std::size_t i = 0; i < b.size(); ++i)
    b.d[i] = A * b.cloud.X[i] + 0.05 * h * Vec3(u(rng), u(rng), u(rng));
  if (materials::lce::material_of(b))
    for (auto& hv : materials::lce::material_of(b)->director.h) hv = (hv + 0.2 * Vec3(u(rng), u(rng), u(rng))).normalized();
}

struct Reference {
  std::vector<Vec3> force, frank_divergence;
  double stabilization_energy = 0.0;
};

// The unfused computation, from the rk/ building blocks and the material.
Reference unfused(Body& b) {
  Reference r;
  std::vector<Mat3> F, grad_h, P(b.size()), flux(b.size());
  std::vector<Vec3> x(b.size());
  for (std::size_t I = 0; I < b.size(); ++I) x[I] = nodal_position(b, static_cast<Index>(I));
  rk::deformation_gradients(b.gradient, x, F);
  const auto* lce = std::get_if<materials::lce::BodyMaterial>(&b.material);
  if (lce) rk::deformation_gradients(b.gradient, materials::lce::material_of(b)->director.h, grad_h);
  for (std::size_t L = 0; L < b.size(); ++L) {
    if (lce) {
      const auto p = materials::lce::director_point(materials::lce::material_of(b)->director, static_cast<Index>(L), grad_h[L]);
      P[L] = lce->model.first_piola(F[L], p);
      flux[L] = lce->model.frank_flux(F[L], p);
    } else {
      P[L] = std::get<materials::mooney_rivlin::BodyMaterial>(b.material).at_point[L].first_piola(F[L]);
    }
  }
  rk::internal_forces(b.gradient, P, r.force);
  for (auto& f : r.force) f = -f;
  rk::Stabilization stab = b.stabilization;
  r.stabilization_energy = rk::add_stabilization_forces(b.interpolation, stab, b.d, r.force);
  if (lce) {
    rk::internal_forces(b.gradient, flux, r.frank_divergence);
    for (std::size_t I = 0; I < b.size(); ++I) r.frank_divergence[I] /= -b.cloud.volume[I];
  }
  return r;
}

double max_norm(const std::vector<Vec3>& v) {
  double m = 0.0;
  for (const auto& x : v) m = std::max(m, x.norm());
  return m;
}

double max_difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, (a[i] - b[i]).norm());
  return m;
}

void check_against_unfused(const std::string& cloud, const std::string& material) {
  ScopedThreads one(1);
  // The unfused products read the double operator; the fused pass must equal them to
  // double round-off.
  auto sw = build_from_text(with(with(kScene, "cloud", cloud), "material", material) +
                            "[body.rk]\ngradient_precision = \"double\"\n");
  Body& b = *sw.world->bodies.front();
  ASSERT_TRUE(b.stabilization.active());
  deform(b);
  const Reference ref = unfused(b);
  compute_internal_forces(b);
  const double scale = max_norm(ref.force);
  ASSERT_GT(scale, 0.0);
  EXPECT_LT(max_difference(b.force, ref.force), 1e-12 * scale);
  EXPECT_NEAR(b.stabilization_energy, ref.stabilization_energy, 1e-12 * ref.stabilization_energy);
  EXPECT_GT(ref.stabilization_energy, 0.0);
  if (materials::lce::material_of(b) && materials::lce::material_of(b)->director.frank) {
    const double div_scale = max_norm(ref.frank_divergence);
    ASSERT_GT(div_scale, 0.0);
    EXPECT_LT(max_difference(materials::lce::material_of(b)->director.frank_divergence, ref.frank_divergence), 1e-12 * div_scale);
  }

  // Two threads: the same forces up to round-off, and bitwise the same on a repeat.
  ScopedThreads two(2);
  compute_internal_forces(b);
  const std::vector<Vec3> first = b.force;
  EXPECT_LT(max_difference(first, ref.force), 1e-12 * scale);
  compute_internal_forces(b);
  EXPECT_EQ(max_difference(first, b.force), 0.0);
}

}  // namespace

TEST(ForcePass, LceWithFrankTermAndStabilizationEqualsTheUnfusedProducts) {
  check_against_unfused("generator = \"sphere\"\nradius = 2e-6\ncells = 5", kLce);
}

TEST(ForcePass, MooneyRivlinBlockEqualsTheUnfusedProducts) {
  check_against_unfused("generator = \"block\"\nsize = [4e-6, 3e-6, 2e-6]\ncells = [6, 5, 4]\njitter = 0.2",
                        kMooneyRivlin);
}

// Single-precision storage of the smoothed gradients (rk/nodal_integration.hpp): the same
// forces and Frank divergence as double storage, to the float round-off (entries carry
// 6e-8 relative error; forces are sums of ~1e2 x 1e2 of them), the stabilization (which
// does not read the gradient operator) unchanged.
TEST(ForcePass, SinglePrecisionStorageGivesTheDoubleForcesToItsRoundOff) {
  ScopedThreads two(2);
  const std::string text = with(with(kScene, "cloud", "generator = \"sphere\"\nradius = 2e-6\ncells = 5"), "material", kLce);
  auto reference = build_from_text(text + "[body.rk]\ngradient_precision = \"double\"\n");
  auto single = build_from_text(text + "[body.rk]\ngradient_precision = \"float\"\n");
  Body& d = *reference.world->bodies.front();
  Body& f = *single.world->bodies.front();
  ASSERT_FALSE(d.gradient.single_precision());
  ASSERT_TRUE(f.gradient.single_precision());
  EXPECT_EQ(f.gradient.col, d.gradient.col);
  deform(d);
  deform(f);
  compute_internal_forces(d);
  compute_internal_forces(f);
  const double scale = max_norm(d.force);
  ASSERT_GT(scale, 0.0);
  const double force_error = max_difference(f.force, d.force) / scale;
  const double divergence_error =
      max_difference(materials::lce::material_of(f)->director.frank_divergence, materials::lce::material_of(d)->director.frank_divergence) / max_norm(materials::lce::material_of(d)->director.frank_divergence);
  std::cout << "float against double storage: force " << force_error << ", Frank divergence " << divergence_error
            << " (relative to the largest)\n";
  EXPECT_LT(force_error, 1e-6);
  EXPECT_GT(force_error, 0.0);  // the storage did change
  EXPECT_LT(divergence_error, 1e-6);
  EXPECT_EQ(f.stabilization_energy, d.stabilization_energy);
}

// Without a reader of the Frank divergence in the step (L = 0, no director criterion)
// the pass leaves it out (DirectorField::frank_divergence_tracked): the force keeps its
// bits, and director_residual makes the divergence itself, to round-off the tracked one.
TEST(ForcePass, UntrackedFrankDivergenceKeepsTheForceAndTheDirectorResidual) {
  ScopedThreads two(2);
  auto sw = build_from_text(with(with(kScene, "cloud", "generator = \"sphere\"\nradius = 2e-6\ncells = 5"), "material", kLce));
  Body& b = *sw.world->bodies.front();
  ASSERT_TRUE(materials::lce::material_of(b) && materials::lce::material_of(b)->director.frank);
  ASSERT_FALSE(state_evolves_in_time(b));  // kLce declares no mobility
  deform(b);
  materials::lce::material_of(b)->director.frank_divergence_tracked = true;
  compute_internal_forces(b);
  const std::vector<Vec3> tracked_force = b.force;
  const std::vector<Vec3> tracked_divergence = materials::lce::material_of(b)->director.frank_divergence;
  const double tracked_residual = state_residual(b);
  ASSERT_GT(max_norm(tracked_divergence), 0.0);

  materials::lce::material_of(b)->director.frank_divergence_tracked = false;
  std::fill(materials::lce::material_of(b)->director.frank_divergence.begin(), materials::lce::material_of(b)->director.frank_divergence.end(), Vec3::Zero());
  compute_internal_forces(b);
  EXPECT_EQ(max_difference(b.force, tracked_force), 0.0);
  EXPECT_EQ(max_norm(materials::lce::material_of(b)->director.frank_divergence), 0.0);  // not assembled
  std::vector<Vec3> made;
  materials::lce::material_of(b)->frank_divergence(b, made);
  EXPECT_LT(max_difference(made, tracked_divergence), 1e-12 * max_norm(tracked_divergence));
  EXPECT_NEAR(state_residual(b), tracked_residual, 1e-12 * tracked_residual);
  ASSERT_GT(tracked_residual, 0.0);
}
