// Releases from large strain (docs/verification/stability.md): the stability study's free
// Mooney-Rivlin block (6^3 cells, lambda / c1 = 10, undamped) let go from stretch 3 or
// compression 0.3 along x. At the default schedule (the stable step re-estimated every
// 10 steps) the state changes faster than the step follows and the run blows up
// (printed below, not asserted: a better estimate may one day hold it; the stability
// study records when); with `stable_step_interval = 1` it runs to its end with the
// energy ledger balanced.
// Damped (mass-proportional, 3e6 / s, ten times an estimate of the block's slowest
// angular frequency, pi c_s / L ~ 3e5 rad/s with c_s = 1 m/s; 1e6 / s does not hold the
// compression in all directions, docs/verification/stability.md) with the step estimated every step,
// the releases along x and in all directions come to rest in the stress-free state.
#include "sim_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace rkpm::sim {
namespace {

using testing::build_from_text;
using testing::with;

const std::string kReleasedBlock = R"([scene]
name = "release"
[integrator]
t_end = {t_end}
stable_step_interval = {interval}
damping = {damping}
[[body]]
name = "block"
density = 1000
[body.cloud]
generator = "block"
size = [1e-5, 1e-5, 1e-5]
cells = [6, 6, 6]
jitter = 0.1
[body.material]
model = "mooney_rivlin"
c1 = 400
c2 = 100
lambda = 4000
[body.initial]
stretch = {stretch}
)";

struct Release {
  bool blew_up = false;
  std::int64_t steps = 0;
  double time = 0.0;
  double t_end = 0.0;  // [s] the scene's end time
  double max_energy_error = 0.0;
  double min_J = 1e300;
  int stable_dt_changes = 0;  // steps after which stable_dt() differed from the step before
  double initial_energy = 0.0;  // [J] stored at the release
  double final_kinetic = 0.0;   // [J]
  double final_strain = 0.0;    // [J]
  double final_min_J = 0.0;
};

// The release's scene: undamped to 2e-5 s (the stability study's span), or damped by
// `damping` [1/s] to 1e-4 s (the damped block is at rest by 5e-5 s).
struct ReleaseCase {
  int interval = 10;
  std::string stretch;
  double damping = 0.0;
  std::int64_t step_cap = 20000;  // about 4x the steps the undamped releases take
};

Release release(const ReleaseCase& c) {
  testing::ScopedThreads one(1);
  std::string text = with(kReleasedBlock, "interval", std::to_string(c.interval));
  text = with(text, "stretch", c.stretch);
  text = with(text, "damping", std::to_string(c.damping));
  text = with(text, "t_end", c.damping > 0.0 ? "1e-4" : "2e-5");
  auto sw = build_from_text(text);
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  Release r;
  r.t_end = sw.scene.integrator.real("t_end");
  r.initial_energy = integrator.measure_energy().initial;
  try {
    while (sw.world->time < r.t_end && sw.world->step < c.step_cap) {
      const double before = integrator.stable_dt();
      integrator.step();
      if (integrator.stable_dt() != before) ++r.stable_dt_changes;
      r.max_energy_error = std::max(r.max_energy_error, integrator.measure_energy().relative_error());
      r.min_J = std::min(r.min_J, integrator.min_J());
    }
  } catch (const BlowUp&) {
    r.blew_up = true;
  }
  r.steps = sw.world->step;
  r.time = sw.world->time;
  if (!r.blew_up) {
    const EnergyLedger& end = integrator.measure_energy();
    r.final_kinetic = end.kinetic;
    r.final_strain = end.strain;
    r.final_min_J = integrator.min_J();
  }
  std::printf("stretch %s, damping %g / s, stable step every %d steps: %lld steps to t = %.3g s, smallest J %.3f "
              "(%.4f at the end), stored energy left %.1e of the released, largest relative energy error %.3e%s\n",
              c.stretch.c_str(), c.damping, c.interval, static_cast<long long>(r.steps), r.time, r.min_J,
              r.final_min_J, r.final_strain / r.initial_energy, r.max_energy_error, r.blew_up ? " (blew up)" : "");
  return r;
}

TEST(ReleaseFromLargeStrain, AStableStepEstimatedEveryStepCarriesTheReleasesAlongAnAxisToTheEnd) {
  for (const char* stretch : {"[3.0, 1.0, 1.0]", "[0.3, 1.0, 1.0]"}) {
    const Release r = release({1, stretch});
    EXPECT_FALSE(r.blew_up) << stretch;
    EXPECT_GE(r.time, r.t_end) << stretch << ": stopped at the step cap";
    // Undamped: kinetic plus stored energy stays the released energy, up to velocity
    // Verlet's O(dt^2) oscillation (0.6 % and 1.0 % measured).
    EXPECT_LE(r.max_energy_error, 0.03) << stretch;
  }
}

// The key sets the schedule: over the first 30 steps of the release, whose state changes
// in every step, the estimate moves after every step with interval 1 and only at the
// 10th, 20th and 30th with the default. The default run's outcome is printed.
TEST(ReleaseFromLargeStrain, TheIntervalSetsHowOftenTheStableStepIsEstimated) {
  const Release every_step = release({1, "[3.0, 1.0, 1.0]", 0.0, 30});
  const Release every_ten = release({10, "[3.0, 1.0, 1.0]", 0.0, 30});
  EXPECT_EQ(every_step.steps, 30);
  EXPECT_GE(every_step.stable_dt_changes, 29);
  EXPECT_EQ(every_ten.steps, 30);
  EXPECT_GE(every_ten.stable_dt_changes, 2);
  EXPECT_LE(every_ten.stable_dt_changes, 3);
  for (const char* stretch : {"[3.0, 1.0, 1.0]", "[0.3, 1.0, 1.0]"}) (void)release({10, stretch});
}

// Run to rest: damped, every release ends in the stress-free state, its stored and kinetic
// energy gone to the damper and the ledger balanced. Measured: the stored
// energy left 2e-7 to 3e-5 of the released, J at the end 0.993-0.999 (the overdamped
// slowest modes still creeping), ledger error 0.2-0.7 %. Undamped, the releases in all
// directions blow up early, and so does the release from stretch 3 in all directions
// damped with the default schedule (all printed, not asserted; when each blows up is in
// docs/verification/stability.md).
TEST(ReleaseFromLargeStrain, DampedReleasesAlongAnAxisAndInAllDirectionsComeToRest) {
  constexpr double kDamping = 3e6;  // [1/s]
  for (const char* stretch : {"[3.0, 1.0, 1.0]", "[0.3, 1.0, 1.0]", "[3.0, 3.0, 3.0]", "[0.3, 0.3, 0.3]"}) {
    const Release r = release({1, stretch, kDamping});
    ASSERT_FALSE(r.blew_up) << stretch;
    EXPECT_GE(r.time, r.t_end) << stretch << ": stopped at the step cap";
    EXPECT_LT(r.final_kinetic, 1e-6 * r.initial_energy) << stretch;
    EXPECT_LT(r.final_strain, 1e-4 * r.initial_energy) << stretch;
    EXPECT_GT(r.final_min_J, 0.98) << stretch;
    EXPECT_LE(r.max_energy_error, 0.02) << stretch;
  }
  for (const char* stretch : {"[3.0, 3.0, 3.0]", "[0.3, 0.3, 0.3]"}) (void)release({1, stretch});
  (void)release({10, "[3.0, 3.0, 3.0]", kDamping});
}

}  // namespace
}  // namespace rkpm::sim
