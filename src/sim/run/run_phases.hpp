// run_scene's phases around its loop: set-up (everything that can fail on the user's
// input, before anything is written), the nested levels, the start of the output, and
// the conclusion (summary.json and the log's last words). run.cpp runs them in order.
#pragma once

#include "sim/run/run_loop.hpp"
#include "sim/run/run_output.hpp"

#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/checkpoint.hpp"
#include "rkpm/sim/integrator.hpp"
#include "rkpm/sim/nested_iteration.hpp"
#include "rkpm/sim/preflight.hpp"
#include "rkpm/sim/run.hpp"

#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace rkpm::sim {

// A run that stops before its loop: the exit code and the message the log gets.
struct RunRefused {
  int code;
  std::string message;
};

struct RunSetup {
  RunEstimate estimate;
  std::unique_ptr<World> world;
  IntegratorSettings settings;
  std::unique_ptr<Integrator> integrator;
  const Body* shape_body = nullptr;  // [output] shape_report's body, or null
};

// What the scene will cost is checked before anything large is allocated; then the
// world, the checks of the built world and the integrator. Throws RunRefused.
RunSetup set_up(const scene::Scene& scene, const RunOptions& options, std::ostream& log);

// Nested iteration: the coarse levels relax before the fine run starts from their
// state, each with its own progress line. Throws RunRefused.
std::vector<LevelRun> relax_levels(const scene::Scene& scene, RunSetup& s, const RunOptions& options,
                                   std::ostream& log, const std::function<double()>& elapsed);

// The integrator's first forces and step, then the checks that need the step (the
// frames fit the disk) and the output folder. Throws RunRefused.
void start(const scene::Scene& scene, RunSetup& s, const RunOptions& options);

// Opens the frames and history.csv; a restart first reads its checkpoint into the
// world, the integrator and `clock`. Throws RunRefused.
std::unique_ptr<RunOutput> open_output(const scene::Scene& scene, RunSetup& s, const RunOptions& options,
                                       RunClock& clock);

// What the step size turned out to be, when the user should know.
void report_step_size(const RunSetup& s, std::ostream& log);

// summary.json and the log's last words; returns the exit code (a summary that cannot
// be written turns a success into kOutputFailed).
int conclude(const scene::Scene& scene, RunSetup& s, const RunOptions& options, const std::vector<LevelRun>& levels,
             const LoopEnd& end, const RunOutput& output, double wall_time, std::ostream& log);

}  // namespace rkpm::sim
