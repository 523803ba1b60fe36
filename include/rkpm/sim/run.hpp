// Running a scene from start to finish: set-up, time loop, frames, checkpoints,
// the summary, and the exit status the command line reports.
#pragma once

#include "rkpm/par/comm.hpp"
#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/integrator.hpp"
#include "rkpm/sim/preflight.hpp"
#include "rkpm/sim/world.hpp"

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>

namespace rkpm::sim {

// Process exit codes of `rkpm run`.
enum ExitCode : int {
  kSuccess = 0,
  kInternalError = 1,
  kBadInput = 2,     // the scene (or a file it names) is wrong; nothing was written
  kUnstable = 3,     // the simulation blew up; the last good frame is kept
  kIncomplete = 4,   // max_steps (or, relaxing, t_end) was reached before t_end or convergence
  kOutputFailed = 5, // the output folder could not be created or written (disk full, no permission);
                     // the frames listed in the .pvd are complete, the last checkpoint is usable
};

// A run's world and integrator at its end, for a caller that reads the final state or
// steps on (the Python module). The integrator refers to the world.
struct RunState {
  std::unique_ptr<World> world;
  std::unique_ptr<Integrator> integrator;
};

struct RunOptions {
  std::filesystem::path out_dir;      // where frames, checkpoints and summary.json go
  std::filesystem::path restart;      // checkpoint to resume from (empty: start fresh)
  std::int64_t max_steps_override = 0;  // > 0: stop (successfully) after this many steps
  bool allow_unstable_dt = false;     // testing: keep a user dt above the stable estimate
  bool quiet = false;                 // no progress line
  RunLimits limits;                   // memory and disk the run must fit in (default: the machine's)
  // The ranks the run is distributed over. On more than one, rank 0 alone writes the
  // log, history.csv, summary.json and the .pvd; each rank writes its piece of every
  // frame and its own checkpoint (`checkpoint.bin.<rank>`; `restart` names the file
  // without the suffix).
  const par::Comm* comm = &par::Comm::world();
  // Called after every step of the main loop (not the nested levels'); returning false
  // stops the run there, as --max-steps does, with the status "interrupted" and exit
  // code kIncomplete: the final frame and summary.json are written. Distributed, the
  // ranks stop together at the first step where any rank's call returns false.
  std::function<bool(const World&, const Integrator&)> after_step;
  // When set, receives the world and the integrator at the end of a run that got past
  // its set-up, instead of their being destroyed.
  RunState* keep = nullptr;
};

// Runs the scene; messages go to `log` (progress, warnings, diagnoses). Returns an ExitCode.
int run_scene(const scene::Scene& scene, const RunOptions& options, std::ostream& log);

}  // namespace rkpm::sim
