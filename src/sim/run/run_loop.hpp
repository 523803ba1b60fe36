// The time loop of a run (run.cpp): steps, frames, checkpoints and the progress line from the
// first frame to the last, then the relaxation's Newton-Krylov finish if the scene asks
// for it. How the loop ended is its result; the caller writes the summary.
#pragma once

#include "sim/run/run_output.hpp"

#include "rkpm/io/progress.hpp"
#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/checkpoint.hpp"
#include "rkpm/sim/integrator.hpp"
#include "rkpm/sim/run.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <ostream>
#include <string>

namespace rkpm::sim {

// How a run's loop ended: its status for summary.json, its exit code, and for a failure
// the diagnosis.
struct LoopEnd {
  std::string status = "completed";
  int code = kSuccess;
  std::string diagnosis;
  std::optional<NewtonKrylovReport> finish;  // the Newton-Krylov finish's report, if it ran
};

// The relaxation's two criteria for a progress line: a run whose residual is already
// below its target keeps going while the kinetic energy is not (a shape still creeping
// along a soft mode, docs/verification/relaxation.md), and the line says which one it waits for.
std::string relax_progress(const Integrator& integrator, const IntegratorSettings& settings);

class RunLoop {
 public:
  // `elapsed` gives the run's wall time so far [s]. `clock` is the checkpoint's (restored
  // on a restart).
  RunLoop(const scene::Scene& scene, const RunOptions& options, World& world, Integrator& integrator,
          const IntegratorSettings& settings, RunOutput& output, RunClock& clock, std::ostream& log,
          std::function<double()> elapsed);

  // From the first frame (unless resumed) to the final state's frame. A blow-up, a
  // non-finite output value or a failed write ends the loop as its LoopEnd says.
  LoopEnd run();

 private:
  void step_until_done(LoopEnd& end);
  void finish_newton_krylov(LoopEnd& end);
  void write_frame();

  const RunOptions& options_;
  World& world_;
  Integrator& integrator_;
  const IntegratorSettings& settings_;
  RunOutput& output_;
  RunClock& clock_;
  std::ostream& log_;
  std::function<double()> elapsed_;
  const bool relax_;
  const double t_end_, every_;
  const std::int64_t checkpoint_every_, max_steps_;
  const std::uint64_t digest_;
  const std::filesystem::path checkpoint_path_;
  io::Progress progress_;
};

}  // namespace rkpm::sim
