#include "sim/run/run_phases.hpp"

#include "sim/run/collective_output.hpp"
#include "sim/run/summary.hpp"

#include "rkpm/io/json.hpp"
#include "rkpm/io/progress.hpp"
#include "rkpm/io/run_summary.hpp"
#include "rkpm/sim/build.hpp"

#include <fmt/format.h>

#include <filesystem>

namespace rkpm::sim {

namespace {

// Every rank brings its own verdict (its memory, its view of the output folder); the
// lowest failing rank's is the run's, so that no rank goes on to wait for one that stopped.
void agree(const par::Comm& comm, const std::string& refusal, int code) {
  if (const std::string agreed = comm.first_error(refusal); !agreed.empty()) throw RunRefused{code, agreed};
}

}  // namespace

// What the scene will cost is checked before anything large is allocated; then the
// world, the checks of the built world and the integrator.
RunSetup set_up(const scene::Scene& scene, const RunOptions& options, std::ostream& log) {
  const par::Comm& comm = *options.comm;
  RunSetup s;
  std::string refusal;
  try {
    s.estimate = estimate_run(scene, comm.size(), comm.node_size());
    check_memory(s.estimate, options.limits);
  } catch (const PreflightError& e) {
    refusal = e.what();
  }
  agree(comm, refusal, kBadInput);
  try {
    s.world = build_world(scene, comm);
    check_distributable_terms(scene, *s.world);
    check_newton_krylov_finish(scene, *s.world);
  } catch (const SetupError& e) {
    throw RunRefused{kBadInput, e.what()};
  }
  for (const auto& w : s.world->setup_warnings) log << "warning: " << w << "\n";
  s.settings = integrator_settings(scene);
  s.settings.allow_unstable_dt = options.allow_unstable_dt;
  s.integrator = std::make_unique<Integrator>(*s.world, s.settings);
  if (const std::string name = scene.output.text("shape_report"); !name.empty()) {
    s.shape_body = s.world->find_body(name);
    if (!s.shape_body || s.shape_body->cloud.surface_bit("outer") == 0u)
      throw RunRefused{kBadInput, fmt::format("{}:{}: [output] shape_report = \"{}\": expected the name of a shell body",
                                              scene.output.file(), scene.output.line("shape_report"), name)};
  }
  return s;
}

// Nested iteration: the coarse levels relax before the fine run starts from their state.
// Each level gets its own progress line, labelled with the level, so that a long coarse
// relaxation shows its residual and kinetic criterion like the fine run.
std::vector<LevelRun> relax_levels(const scene::Scene& scene, RunSetup& s, const RunOptions& options,
                                   std::ostream& log, const std::function<double()>& elapsed) {
  std::unique_ptr<io::Progress> level_progress;
  const std::size_t level_count = nested_level_factors(scene).size();
  LevelStepCallback show;
  if (!options.quiet)
    show = [&](std::size_t l, const World& level, const Integrator& level_integrator, bool done) {
      if (!level_progress) level_progress = std::make_unique<io::Progress>(log, io::stderr_is_terminal());
      level_progress->update(level.step, level.time, 0.0, level_integrator.dt(), elapsed(),
                             fmt::format("level {}/{}: {}", l + 1, level_count,
                                         relax_progress(level_integrator, s.settings)));
      if (done) {
        level_progress->finish();
        level_progress.reset();
      }
    };
  try {
    return relax_coarse_levels(scene, *s.world, log, show);
  } catch (const SetupError& e) {
    throw RunRefused{kBadInput, e.what()};
  } catch (const BlowUp& e) {
    throw RunRefused{kUnstable, e.what()};
  }
}

// The step is known once the integrator has started: the frames a dynamic run writes
// must fit the output folder before the first is written. A state that fails the
// checks before the first step is the scene's (bodies declared overlapping, a force
// that overflows at once): refused as input, nothing written.
void start(const scene::Scene& scene, RunSetup& s, const RunOptions& options) {
  const par::Comm& comm = *options.comm;
  try {
    s.integrator->initialize();
  } catch (const BlowUp& e) {
    throw RunRefused{kBadInput, std::string("the scene's initial state: ") + e.what()};
  }
  std::string refusal;
  try {
    check_disk(scene, s.estimate,
               frames_expected(scene, s.estimate, s.integrator->dt(), options.max_steps_override), options.limits,
               options.out_dir);
  } catch (const PreflightError& e) {
    refusal = e.what();
  }
  agree(comm, refusal, kBadInput);
  refusal.clear();
  try {
    std::filesystem::create_directories(options.out_dir);
  } catch (const std::filesystem::filesystem_error& e) {
    refusal = fmt::format("cannot create the output folder '{}': {}", options.out_dir.string(), e.code().message());
  }
  agree(comm, refusal, kOutputFailed);
}

// Opens the frames and history.csv; a restart first reads its checkpoint (every rank
// its own file: a failure on any is the run's).
std::unique_ptr<RunOutput> open_output(const scene::Scene& scene, RunSetup& s, const RunOptions& options,
                                       RunClock& clock) {
  const par::Comm& comm = *options.comm;
  const bool resume = !options.restart.empty();
  const auto cells = scene.output.choice("cells") == "points" ? CellOutput::Points : CellOutput::Mesh;
  if (resume) try {
      collective_output(comm, [&] {
        read_checkpoint(rank_file(options.restart, comm), *s.world, *s.integrator, clock, file_digest(scene.file));
      });
    } catch (const std::exception& e) {
      throw RunRefused{kBadInput, e.what()};
    }
  try {
    return std::make_unique<RunOutput>(comm, options.out_dir, *s.world, s.shape_body, cells, resume);
  } catch (const ResumeRefused& e) {
    throw RunRefused{kBadInput, e.what()};
  } catch (const std::exception& e) {
    throw RunRefused{kOutputFailed, e.what()};
  }
}

// What the step size turned out to be, when the user should know.
void report_step_size(const RunSetup& s, std::ostream& log) {
  const Integrator& integrator = *s.integrator;
  if (integrator.dt_clamped())
    log << fmt::format("warning: [integrator] dt = {:.3g} s exceeds the stable step {:.3g} s; using {:.3g} s\n",
                       s.settings.dt, integrator.stable_dt(), integrator.dt());
  if (integrator.measures_stable_step() && !s.settings.measured_stable_step)
    log << fmt::format("note: the essential boundary conditions amplify (a unit motion of the free coordinates "
                       "moves a constrained one by {:.3g}): the stable step is measured (stable_step = \"auto\")\n",
                       integrator.constraint_amplification());
  if (integrator.measures_stable_step())
    log << fmt::format("stable step {:.4g} s: measured 2 / omega_max, {:.3g} x the wave-speed estimate\n",
                       integrator.stable_dt(), integrator.stable_step_calibration());
}

// summary.json and the log's last words; returns the exit code (a summary that cannot
// be written turns a success into kOutputFailed).
int conclude(const scene::Scene& scene, RunSetup& s, const RunOptions& options, const std::vector<LevelRun>& levels,
             const LoopEnd& end, const RunOutput& output, double wall_time, std::ostream& log) {
  const par::Comm& comm = *options.comm;
  const World& world = *s.world;
  const bool relax = s.settings.mode == Mode::Relax;
  const RunOutcome outcome{end.status, end.code, end.diagnosis, wall_time, output.frames_written(), output.pvd_path()};
  io::Json json = run_summary(scene, world, *s.integrator, relax, levels, end.finish, outcome, s.shape_body,
                              options.out_dir);
  int code = end.code;
  if (code == kUnstable || code == kOutputFailed) {
    log << "error: " << end.diagnosis << "\n";
    log << fmt::format(code == kUnstable ? "the last good frame is kept in {}" : "the frames listed in {} are complete",
                       output.pvd_path().string());
    const auto checkpoint_path = rank_file(options.out_dir / "checkpoint.bin", comm);
    if (code == kOutputFailed && scene.output.integer("checkpoint_every") > 0 && std::filesystem::exists(checkpoint_path))
      log << fmt::format("; {} can resume the run (--restart)", checkpoint_path.string());
    log << "\n";
  }
  try {
    collective_output(comm, [&] {
      if (comm.root()) io::write_json_atomically(options.out_dir / "summary.json", json);
    });
  } catch (const std::exception& e) {
    // The run's own verdict stands; a summary that cannot be written is reported beside it.
    log << "error: cannot write summary.json: " << e.what() << "\n";
    if (code == kSuccess || code == kIncomplete) code = kOutputFailed;
  }
  if (code == kSuccess || code == kIncomplete)
    log << fmt::format("{} after {} steps, t = {:.6g} s, {:.1f} s wall. ParaView: {}\n", end.status, world.step,
                       world.time, outcome.wall_time, output.pvd_path().string());
  return code;
}

}  // namespace rkpm::sim
