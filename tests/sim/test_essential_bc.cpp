// The transformation method's force (essential_bc.hpp): for every admissible variation
// delta d (free coordinates moved, constrained ones following through impose) the
// transformed force must do the work the full force does, f~_F . delta d_F = f . delta d,
// which is what f~_F = f_F - Lambda_CF^T Lambda_CC^-T f_C means. Lambda_CC is not
// symmetric (Psi_I(X_J) != Psi_J(X_I) on a jittered cloud), so a solve with Lambda_CC in
// place of its transpose fails this check.
#include "sim_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace rkpm::sim {
namespace {

const std::string kClampedBlock = R"([scene]
name = "essential_bc"
[integrator]
t_end = 1.0
[[body]]
name = "block"
density = 1000
[body.cloud]
generator = "block"
size = [1, 0.8, 0.6]
cells = [4, 3, 3]
jitter = 0.2
[body.material]
model = "mooney_rivlin"
c1 = 400
c2 = 100
lambda = 2000
[[body.boundary]]
surface = "xmin"
axes = "xyz"
[[body.boundary]]
surface = "ymax"
axes = "z")";

double dot(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i].dot(b[i]);
  return s;
}

TEST(EssentialBC, TransformedForceDoesTheWorkOfTheFullForceOnAdmissibleVariations) {
  testing::ScopedThreads one(1);
  auto sw = testing::build_from_text(kClampedBlock);
  Body& b = *sw.world->bodies.front();
  ASSERT_FALSE(b.constraints.empty());
  const std::size_t n = b.size();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto random_field = [&] {
    std::vector<Vec3> v(n);
    for (auto& x : v) x = Vec3(u(rng), u(rng), u(rng));
    return v;
  };

  // A constrained state d0, and the asymmetry of Lambda_CC that the check relies on.
  std::vector<Vec3> d0 = random_field(), velocity(n, Vec3::Zero());
  for (auto& x : d0) x *= 1e-3;
  b.constraints.impose(d0, velocity);

  const std::vector<Vec3> f = random_field();
  std::vector<Vec3> transformed = f;
  b.constraints.transform_forces(transformed);

  double worst = 0.0;
  for (int trial = 0; trial < 5; ++trial) {
    // Move the free coordinates; impose moves the constrained ones to keep the targets.
    std::vector<Vec3> d1 = d0;
    const std::vector<Vec3> r = random_field();
    for (std::size_t i = 0; i < n; ++i)
      for (int a = 0; a < 3; ++a)
        if (!b.constraints.constrained(static_cast<Index>(i), a)) d1[i][a] += 1e-3 * r[i][a];
    b.constraints.impose(d1, velocity);
    std::vector<Vec3> delta(n);
    for (std::size_t i = 0; i < n; ++i) delta[i] = d1[i] - d0[i];
    // The constrained coordinates moved too: otherwise the check would be trivial.
    double constrained_motion = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      for (int a = 0; a < 3; ++a)
        if (b.constraints.constrained(static_cast<Index>(i), a))
          constrained_motion = std::max(constrained_motion, std::abs(delta[i][a]));
    ASSERT_GT(constrained_motion, 1e-6);
    const double full = dot(f, delta), reduced = dot(transformed, delta);
    worst = std::max(worst, std::abs(full - reduced) / std::abs(full));
  }
  std::printf("largest |f . dd - f~ . dd| / |f . dd| over 5 admissible variations: %.2e\n", worst);
  EXPECT_LE(worst, 1e-10);
}

}  // namespace
}  // namespace rkpm::sim
