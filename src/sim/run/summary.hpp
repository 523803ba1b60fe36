// summary.json of a run (docs/guide/outputs.md): what the run loop hands over at its end,
// and the JSON it becomes. Written once by the run loop (rank 0), built on every rank.
#pragma once

#include "rkpm/io/json.hpp"
#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/integrator.hpp"
#include "rkpm/sim/nested_iteration.hpp"
#include "rkpm/sim/newton_krylov.hpp"
#include "rkpm/sim/world.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rkpm::sim {

// How the run ended, and what it wrote.
struct RunOutcome {
  std::string status;         // "completed", "unstable", "interrupted", ...
  int code = 0;               // the exit code (rkpm/sim/run.hpp)
  std::string diagnosis;      // why it failed (unstable, output failed); empty otherwise
  double wall_time = 0.0;     // [s], set-up included
  std::int64_t frames_written = 0;
  std::filesystem::path pvd;  // the frames' series
};

// The summary: the run's counts and outcome, its distribution over the ranks, the step
// and its control, the nested levels and the Newton-Krylov finish it ran, and, unless
// it failed, the energy ledger, the relaxation's criteria, each term's report and the
// shape report (whose profile it writes to out_dir/shape_profile.csv on rank 0).
// Collective: every rank calls it. Non-const integrator: the ledger is measured here.
io::Json run_summary(const scene::Scene& scene, const World& world, Integrator& integrator, bool relax,
                     const std::vector<LevelRun>& levels, const std::optional<NewtonKrylovReport>& finish,
                     const RunOutcome& outcome, const Body* shape_body, const std::filesystem::path& out_dir);

}  // namespace rkpm::sim
