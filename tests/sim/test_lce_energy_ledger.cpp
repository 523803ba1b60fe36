// The energy ledger closes for an active liquid-crystal-elastomer body whose
// director evolves (Eq. 5-7): the stored energy changed by the director update is
// booked as director work and the active stress (Eq. 1) as work done on the body.
#include "sim_fixtures.hpp"

#include <gtest/gtest.h>

#include <iostream>

using namespace rkpm;
using namespace rkpm::sim;
using namespace rkpm::sim::testing;

namespace {

const char* kBall = R"(
[scene]
name = "lce_ledger"
[integrator]
mode = "dynamic"
t_end = 1e-6
dt_safety = 0.1
[[body]]
name = "ball"
density = 1000.0
[body.cloud]
generator = "sphere"
radius = 2e-6
cells = 4
[body.material]
model = "lce"
mu = 1e4
bulk = 1e6
s = 2.0
kappa = 1e-11
mobility = {mobility}
zeta = {zeta}
[body.director]
initial = "radial"
boundary = "free"
[body.initial]
random_velocity = 0.3
stretch = {stretch}
)";

struct BallRun {
  EnergyLedger energy;
  std::int64_t step_backs = 0;
};

// The ball in a dynamic run, or relaxed by the named relax_method.
BallRun run_ball(const std::string& mobility, const std::string& zeta, const std::string& stretch, int steps,
                 const std::string& relax_method = "") {
  ScopedThreads one(1);
  std::string text = with(with(with(kBall, "mobility", mobility), "zeta", zeta), "stretch", stretch);
  if (!relax_method.empty()) {
    const std::string dynamic = "mode = \"dynamic\"\nt_end = 1e-6";
    text.replace(text.find(dynamic), dynamic.size(), "mode = \"relax\"\nrelax_method = \"" + relax_method + "\"");
  }
  auto sw = build_from_text(text);
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  for (int i = 0; i < steps; ++i) integrator.step();
  return {integrator.measure_energy(), integrator.step_backs()};
}

}  // namespace

TEST(LceEnergyLedger, DirectorUpdatesAreBooked) {
  // Released from a stretch, the radial director is off its equilibrium and relaxes.
  const auto e = run_ball("1e-2", "0", "[1.2, 0.9, 0.95]", 600).energy;
  std::cout << "evolving director: director work " << e.state << " J of initial " << e.initial
            << " J, relative ledger error " << e.relative_error() << "\n";
  EXPECT_GT(std::abs(e.state), 1e-2 * e.initial);  // the director update did change the energy
  EXPECT_LT(e.relative_error(), 2e-3);
}

TEST(LceEnergyLedger, ActiveStressWorkIsBooked) {
  const auto e = run_ball("1e-3", "-5e3", "[1, 1, 1]", 600).energy;
  std::cout << "active ball: active work " << e.active << " J of initial " << e.initial
            << " J, relative ledger error " << e.relative_error() << "\n";
  EXPECT_GT(std::abs(e.active), 0.1 * e.initial);  // activity did significant work
  EXPECT_LT(e.relative_error(), 5e-3);
}

// The ledger closes when FIRE 2.0 relaxes an active body. Its step backs move the body by
// half a step after FIRE; the active stress works along that jump too and stores
// nothing, so Integrator::step_back dissipates the jump's active work with the loads'.
// This ball does not resolve that share: it steps back twice in 600 steps, and the
// error is 4.7e-4 with the share booked and 4.6e-4 without (measured). So the test holds
// the FIRE 2.0 ledger of an active body as a whole (bound 5e-3), not the share itself.
TEST(LceEnergyLedger, ActiveWorkAlongFire2StepBacksIsBooked) {
  const BallRun r = run_ball("1e-3", "-5e3", "[1, 1, 1]", 600, "fire2");
  std::cout << "active ball under FIRE 2.0: " << r.step_backs << " step backs, active work " << r.energy.active
            << " J of initial " << r.energy.initial << " J, relative ledger error " << r.energy.relative_error() << "\n";
  ASSERT_GT(r.step_backs, 0);
  EXPECT_GT(std::abs(r.energy.active), 0.1 * r.energy.initial);
  EXPECT_LT(r.energy.relative_error(), 5e-3);
}
