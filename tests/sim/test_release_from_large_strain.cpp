// Releases from large strain (docs/stability.md): the stability study's free
// Mooney-Rivlin block (6^3 cells, lambda / c1 = 10, undamped) let go from stretch 3 or
// compression 0.3 along x. At the default schedule (the stable step re-estimated every
// 10 steps) the state changes faster than the step follows and the run blew up after
// 740-1,164 steps (printed below, not asserted: a better estimate may one day hold it);
// with `stable_step_interval = 1` it runs to its end with the energy ledger balanced.
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
t_end = 2e-5
stable_step_interval = {interval}
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
};

constexpr std::int64_t kStepCap = 20000;  // about 4x the steps the releases take

Release release(int interval, const std::string& stretch, std::int64_t step_cap = kStepCap) {
  testing::ScopedThreads one(1);
  auto sw = build_from_text(with(with(kReleasedBlock, "interval", std::to_string(interval)), "stretch", stretch));
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  Release r;
  r.t_end = sw.scene.integrator.real("t_end");
  try {
    while (sw.world->time < r.t_end && sw.world->step < step_cap) {
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
  std::printf("stretch %s, stable step every %d steps: %lld steps to t = %.3g s, smallest J %.3f, largest relative "
              "energy error %.3e%s\n",
              stretch.c_str(), interval, static_cast<long long>(r.steps), r.time, r.min_J, r.max_energy_error,
              r.blew_up ? " (blew up)" : "");
  return r;
}

TEST(ReleaseFromLargeStrain, AStableStepEstimatedEveryStepCarriesTheReleasesAlongAnAxisToTheEnd) {
  for (const char* stretch : {"[3.0, 1.0, 1.0]", "[0.3, 1.0, 1.0]"}) {
    const Release r = release(1, stretch);
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
  const Release every_step = release(1, "[3.0, 1.0, 1.0]", 30);
  const Release every_ten = release(10, "[3.0, 1.0, 1.0]", 30);
  EXPECT_EQ(every_step.steps, 30);
  EXPECT_GE(every_step.stable_dt_changes, 29);
  EXPECT_EQ(every_ten.steps, 30);
  EXPECT_GE(every_ten.stable_dt_changes, 2);
  EXPECT_LE(every_ten.stable_dt_changes, 3);
  for (const char* stretch : {"[3.0, 1.0, 1.0]", "[0.3, 1.0, 1.0]"}) (void)release(10, stretch);
}

}  // namespace
}  // namespace rkpm::sim
