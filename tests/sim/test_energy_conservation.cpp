// Undamped elastic vibration: velocity Verlet is symplectic, so the energy of a free
// vibrating Mooney-Rivlin block must stay constant up to an O(dt^2) oscillation
// (no drift) over many periods.
#include "sim_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rkpm::sim {
namespace {

using testing::build_from_text;
using testing::with;

// A free block, initially stretched along x and squeezed along y, so that it rings
// in its breathing and extension modes; no supports, no damping.
const std::string kVibratingBlock = R"([scene]
name = "vibration"
[integrator]
t_end = 1.0
dt_safety = {safety}
[[body]]
name = "block"
density = 1000
[body.cloud]
generator = "block"
size = [1, 1, 1]
cells = [4, 4, 4]
jitter = 0.1
[body.material]
model = "mooney_rivlin"
c1 = 400
c2 = 100
lambda = 2000
[body.initial]
stretch = [1.05, 0.97, 1.0]
)";

struct EnergyRun {
  double max_error = 0.0;        // largest EnergyLedger::relative_error over the run
  double first_window = 0.0;     // largest error over the first `window` steps
  double last_window = 0.0;      // largest error over the last `window` steps
  double dt = 0.0;
  double simulated_time = 0.0;
};

// Steps until `steps` steps or simulated time `t_end` (whichever first), measuring the
// ledger after every step.
EnergyRun run_vibration(double safety, std::int64_t steps, double t_end, std::int64_t window = 0) {
  auto sw = build_from_text(with(kVibratingBlock, "safety", std::to_string(safety)));
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  EnergyRun r;
  r.dt = integrator.dt();
  while (sw.world->step < steps && sw.world->time < t_end) {
    integrator.step();
    const double e = integrator.measure_energy().relative_error();
    r.max_error = std::max(r.max_error, e);
    if (sw.world->step <= window) r.first_window = std::max(r.first_window, e);
    if (sw.world->step > steps - window) r.last_window = std::max(r.last_window, e);
  }
  r.simulated_time = sw.world->time;
  return r;
}

// dt_safety = 0.025: the error is set by omega dt of the block's lowest modes, about
// (omega dt)^2 / 4; this coarse block rings at about 30 steps per period at
// dt_safety = 0.3 (error 1e-2), so 1e-4 needs a step 10 times smaller.
TEST(EnergyConservation, FreeVibratingBlockKeepsItsEnergyOver10000Steps) {
  testing::ScopedThreads one(1);
  const EnergyRun r = run_vibration(0.025, 10000, INFINITY, 2000);
  std::printf("dt_safety 0.025: dt = %.4g s, %.4g s simulated (about 25 periods), max relative energy error %.3e; "
              "max over steps 1-2000 %.3e, over steps 8001-10000 %.3e\n",
              r.dt, r.simulated_time, r.max_error, r.first_window, r.last_window);
  EXPECT_LE(r.max_error, 1e-4);
  // A symplectic integrator oscillates about the true energy; it does not drift.
  EXPECT_LE(r.last_window, 1.3 * r.first_window);
}

// The error of velocity Verlet is O(dt^2): halving the step over the same simulated
// time must divide the largest energy error by about four.
TEST(EnergyConservation, EnergyErrorScalesWithTheSquareOfTheStep) {
  testing::ScopedThreads one(1);
  const double t_end = run_vibration(0.4, 500, INFINITY).simulated_time;
  double previous = 0.0;
  for (double safety : {0.4, 0.2, 0.1, 0.05}) {
    const EnergyRun r = run_vibration(safety, 1000000, t_end);
    std::printf("dt_safety %.3g: dt = %.4g s, max relative energy error %.3e over %.4g s", safety, r.dt, r.max_error,
                r.simulated_time);
    if (previous > 0.0) std::printf(", ratio to the previous step %.2f", previous / r.max_error);
    std::printf("\n");
    if (previous > 0.0) {
      EXPECT_GT(previous / r.max_error, 3.5);
      EXPECT_LT(previous / r.max_error, 4.5);
    }
    previous = r.max_error;
  }
}

}  // namespace
}  // namespace rkpm::sim
