#include "rkpm/sim/run.hpp"

#include "sim/run/collective_output.hpp"
#include "sim/run/summary.hpp"

#include "rkpm/io/json.hpp"
#include "rkpm/io/progress.hpp"
#include "rkpm/io/pvd_series.hpp"
#include "rkpm/io/run_summary.hpp"
#include "rkpm/rk/row_scatter.hpp"
#include "rkpm/sim/build.hpp"
#include "rkpm/sim/checkpoint.hpp"
#include "rkpm/sim/history.hpp"
#include "rkpm/sim/nested_iteration.hpp"
#include "rkpm/sim/output.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <ostream>

namespace rkpm::sim {

namespace {

using Clock = std::chrono::steady_clock;

// The relaxation's two criteria on the progress line: a run whose residual is already
// below its target keeps going while the kinetic energy is not (a shape still creeping
// along a soft mode, docs/verification/relaxation.md), and the line says which one it waits for.
std::string relax_progress(const Integrator& integrator, const IntegratorSettings& settings) {
  std::string line = fmt::format("residual {:.2e} (target {:.0e}), kinetic {:.1e} (target {:.0e})",
                                 integrator.residual(), settings.relax_force_tol, integrator.kinetic_measure(),
                                 settings.relax_velocity_tol);
  if (settings.relax_state_tol > 0.0)
    line += fmt::format(", state {:.1e} (target {:.0e})", integrator.state_measure(), settings.relax_state_tol);
  return line;
}

}  // namespace

int run_scene(const scene::Scene& scene, const RunOptions& options, std::ostream& root_log) {
  const par::Comm& comm = *options.comm;
  std::ostream silent(nullptr);  // the other ranks' messages: rank 0 speaks for the run
  std::ostream& log = comm.root() ? root_log : silent;
  const auto wall_start = Clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - wall_start).count(); };

  // Everything that can fail on user input happens before the output directory exists,
  // and what the scene will cost is checked before anything large is allocated.
  // Each rank reads its own available memory: the verdict is agreed on, so that no rank
  // goes on to wait for one that stopped.
  RunEstimate estimate;
  std::string refusal;
  try {
    estimate = estimate_run(scene, comm.size(), comm.node_size());
    check_memory(estimate, options.limits);
  } catch (const PreflightError& e) {
    refusal = e.what();
  }
  refusal = comm.first_error(refusal);
  if (!refusal.empty()) {
    log << "error: " << refusal << "\n";
    return kBadInput;
  }
  std::unique_ptr<World> world;
  try {
    world = build_world(scene, comm);
    check_distributable_terms(scene, *world);
    check_newton_krylov_finish(scene, *world);
  } catch (const SetupError& e) {
    log << "error: " << e.what() << "\n";
    return kBadInput;
  }
  for (const auto& w : world->setup_warnings) log << "warning: " << w << "\n";
  IntegratorSettings settings = integrator_settings(scene);
  settings.allow_unstable_dt = options.allow_unstable_dt;
  auto integrator_owner = std::make_unique<Integrator>(*world, settings);
  Integrator& integrator = *integrator_owner;
  const bool relax = settings.mode == Mode::Relax;
  const double t_end = scene.integrator.has("t_end") ? scene.integrator.real("t_end") : INFINITY;
  const double every = scene.output.has("every") ? scene.output.real("every") : t_end / 50.0;
  const auto cells = scene.output.choice("cells") == "points" ? CellOutput::Points : CellOutput::Mesh;
  const std::int64_t checkpoint_every = scene.output.integer("checkpoint_every");
  std::int64_t max_steps = scene.integrator.integer("max_steps");
  const std::uint64_t digest = file_digest(scene.file);

  const Body* shape_body = nullptr;
  if (const std::string name = scene.output.text("shape_report"); !name.empty()) {
    shape_body = world->find_body(name);
    if (!shape_body || shape_body->cloud.surface_bit("outer") == 0u) {
      log << fmt::format("error: {}:{}: [output] shape_report = \"{}\": expected the name of a shell body\n",
                         scene.output.file(), scene.output.line("shape_report"), name);
      return kBadInput;
    }
  }
  // Nested iteration: the coarse levels relax before the fine run starts from their state
  // (a restart resumes the fine run itself).
  std::vector<LevelRun> levels;
  if (options.restart.empty()) {
    try {
      // Each level gets its own progress line, labelled with the level, so that a long
      // coarse relaxation shows its residual and kinetic criterion like the fine run.
      std::unique_ptr<io::Progress> level_progress;
      const std::size_t level_count = scene.integrator.reals("nested_levels").size();
      LevelStepCallback show;
      if (!options.quiet)
        show = [&](std::size_t l, const World& level, const Integrator& level_integrator, bool done) {
          if (!level_progress) level_progress = std::make_unique<io::Progress>(log, io::stderr_is_terminal());
          level_progress->update(level.step, level.time, 0.0, level_integrator.dt(), elapsed(),
                                 fmt::format("level {}/{}: {}", l + 1, level_count,
                                             relax_progress(level_integrator, settings)));
          if (done) {
            level_progress->finish();
            level_progress.reset();
          }
        };
      levels = relax_coarse_levels(scene, *world, log, show);
    } catch (const SetupError& e) {
      log << "error: " << e.what() << "\n";
      return kBadInput;
    } catch (const BlowUp& e) {
      log << "error: " << e.what() << "\n";
      return kUnstable;
    }
  }
  // The step is known once the integrator has started: the frames a dynamic run writes
  // must fit the output folder before the first is written.
  // A state that fails the checks before the first step is the scene's (bodies declared
  // overlapping, a force that overflows at once): refused as input, nothing written.
  try {
    integrator.initialize();
  } catch (const BlowUp& e) {
    log << "error: the scene's initial state: " << e.what() << "\n";
    return kBadInput;
  }
  // Each rank checks its own view of the output folder (a node-local disk, free space
  // read at another moment): the verdicts are agreed on, so that no rank goes on alone.
  std::string refused_disk, refused_folder;
  try {
    check_disk(scene, estimate, frames_expected(scene, estimate, integrator.dt(), options.max_steps_override),
               options.limits, options.out_dir);
  } catch (const PreflightError& e) {
    refused_disk = e.what();
  }
  refused_disk = comm.first_error(refused_disk);
  if (!refused_disk.empty()) {
    log << "error: " << refused_disk << "\n";
    return kBadInput;
  }
  try {
    std::filesystem::create_directories(options.out_dir);
  } catch (const std::filesystem::filesystem_error& e) {
    refused_folder = fmt::format("cannot create the output folder '{}': {}", options.out_dir.string(),
                                 e.code().message());
  }
  refused_folder = comm.first_error(refused_folder);
  if (!refused_folder.empty()) {
    log << "error: " << refused_folder << "\n";
    return kOutputFailed;
  }
  const auto checkpoint_path = rank_file(options.out_dir / "checkpoint.bin", comm);
  RunClock clock;
  std::optional<io::PvdSeries> series;
  if (!options.restart.empty()) {
    try {
      // Every rank reads its own file: a failure on any is the run's.
      collective_output(comm, [&] { read_checkpoint(rank_file(options.restart, comm), *world, integrator, clock, digest); });
      collective_output(comm, [&] { series = io::PvdSeries::resume(options.out_dir, "frames", world->time, comm.root()); });
    } catch (const std::exception& e) {
      log << "error: " << e.what() << "\n";
      return kBadInput;
    }
  } else {
    try {
      collective_output(comm, [&] { series.emplace(options.out_dir, "frames", comm.root()); });
    } catch (const std::exception& e) {
      log << fmt::format("error: cannot write the output folder '{}': {}\n", options.out_dir.string(), e.what());
      return kOutputFailed;
    }
  }
  if (integrator.dt_clamped())
    log << fmt::format("warning: [integrator] dt = {:.3g} s exceeds the stable step {:.3g} s; using {:.3g} s\n",
                       settings.dt, integrator.stable_dt(), integrator.dt());
  if (integrator.measures_stable_step() && !settings.measured_stable_step)
    log << fmt::format("note: the essential boundary conditions amplify (a unit motion of the free coordinates "
                       "moves a constrained one by {:.3g}): the stable step is measured (stable_step = \"auto\")\n",
                       integrator.constraint_amplification());
  if (integrator.measures_stable_step())
    log << fmt::format("stable step {:.4g} s: measured 2 / omega_max, {:.3g} x the wave-speed estimate\n",
                       integrator.stable_dt(), integrator.stable_step_calibration());

  std::optional<History> history;
  try {
    collective_output(comm, [&] {
      history.emplace(options.out_dir / "history.csv", *world, shape_body, !options.restart.empty());
    });
  } catch (const std::exception& e) {
    log << "error: " << e.what() << "\n";
    return kOutputFailed;
  }

  std::vector<Vec3> positions;
  auto write_frame = [&] {
    if (!comm.parallel()) {
      collective_output(comm, [&] {
        series->write(world->time, make_frame(*world, cells, positions));
        history->record(*world, integrator);
      });
    } else {
      // Each rank's piece, then the .pvtu and the .pvd once all pieces are on disk.
      io::Frame piece;
      collective_output(comm, [&] { piece = make_frame(*world, cells, positions); });
      collective_output(comm, [&] { series->write_piece(world->time, piece, comm.rank()); });
      collective_output(comm, [&] { series->add_parallel_frame(world->time, piece, comm.size()); });
      collective_output(comm, [&] { history->record(*world, integrator); });
    }
    ++clock.frames;
  };

  io::Progress progress(log, !options.quiet && io::stderr_is_terminal());
  std::optional<NewtonKrylovReport> finish;
  std::string status = "completed", diagnosis;
  int code = kSuccess;
  try {
    if (options.restart.empty()) {
      write_frame();
      clock.next_output = every;
    }
    while (true) {
      const bool time_is_up = world->time >= t_end * (1.0 - 1e-12);
      if (relax ? (world->step > 0 && integrator.converged()) : time_is_up) break;
      if (options.max_steps_override > 0 && world->step >= options.max_steps_override) {
        status = "stopped at --max-steps";  // asked for on the command line: not a failure
        break;
      }
      if (world->step >= max_steps || (relax && time_is_up)) {
        status = relax ? "not converged" : "max_steps reached before t_end";
        code = kIncomplete;
        break;
      }
      integrator.step();
      // A step that ends FIRE before a finish leaves its frame to the finished state
      // (a frame at the same time cannot follow it).
      const bool finish_follows = relax && settings.newton_krylov_finish && integrator.converged();
      if (!finish_follows && world->time >= clock.next_output * (1.0 - 1e-12)) {
        write_frame();
        clock.next_output += every;
      }
      if (checkpoint_every > 0 && world->step % checkpoint_every == 0)
        collective_output(comm, [&] { write_checkpoint(checkpoint_path, *world, integrator, clock, digest); });
      if (!options.quiet)
        progress.update(world->step, world->time, relax ? 0.0 : t_end, integrator.dt(), elapsed(),
                        relax ? relax_progress(integrator, settings) : std::string());
      // Every rank stops at the same step when one caller asks (Ctrl-C reaches the ranks
      // at different steps), or the ranks' collectives would no longer match.
      if (options.after_step && comm.min(options.after_step(*world, integrator) ? 1.0 : 0.0) == 0.0) {
        status = "interrupted";
        code = kIncomplete;
        break;
      }
    }
    if (relax && settings.newton_krylov_finish && code == kSuccess && status == "completed") {
      if (!options.quiet) progress.finish();
      const std::int64_t evaluations_before = integrator.force_evaluations();
      // One line per Newton step (a handful to a few dozen): what a long finish is doing.
      std::function<void(const NewtonKrylovReport&)> report_step;
      if (!options.quiet) report_step = [&](const NewtonKrylovReport& so_far) {
        log << fmt::format("newton-krylov step {}: residual {:.2e} (target {:.0e}), {} GMRES iterations and {} "
                           "force evaluations so far, {:.1f} s\n",
                           so_far.newton_steps, so_far.residual, settings.newton.force_tol, so_far.krylov_iterations,
                           so_far.force_evaluations, elapsed());
        log.flush();
      };
      finish = integrator.finish_newton_krylov(settings.newton, report_step);
      log << fmt::format("newton-krylov: {} after {} Newton steps, {} GMRES iterations, {} force evaluations; "
                         "residual {:.2e} (target {:.0e})\n",
                         finish->stop, finish->newton_steps, finish->krylov_iterations,
                         integrator.force_evaluations() - evaluations_before, finish->residual,
                         settings.newton.force_tol);
      if (!finish->converged) {
        status = "not converged";
        code = kIncomplete;
      }
    }
    // The final state is always in the series.
    if (series->entries().empty() || series->entries().back().time < world->time) write_frame();
  } catch (const BlowUp& e) {
    status = "unstable";
    diagnosis = e.what();
    code = kUnstable;
  } catch (const io::NonFiniteValue& e) {
    status = "unstable";
    diagnosis = fmt::format("a non-finite value reached the output at step {} (t = {:.6g} s): {}", world->step,
                            world->time, e.what());
    code = kUnstable;
  } catch (const OutputFailed& e) {
    status = "output failed";
    diagnosis = fmt::format("writing the output failed at step {} (t = {:.6g} s): {}", world->step, world->time,
                            e.what());
    code = kOutputFailed;
  }
  if (!options.quiet) progress.finish();

  const RunOutcome outcome{status, code, diagnosis, elapsed(), static_cast<std::int64_t>(series->frames_written()),
                           series->pvd_path()};
  io::Json json = run_summary(scene, *world, integrator, relax, levels, finish, outcome, shape_body, options.out_dir);
  if (code == kUnstable || code == kOutputFailed) {
    log << "error: " << diagnosis << "\n";
    log << fmt::format(code == kUnstable ? "the last good frame is kept in {}" : "the frames listed in {} are complete",
                       series->pvd_path().string());
    if (code == kOutputFailed && checkpoint_every > 0 && std::filesystem::exists(checkpoint_path))
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
    log << fmt::format("{} after {} steps, t = {:.6g} s, {:.1f} s wall. ParaView: {}\n", status, world->step,
                       world->time, outcome.wall_time, series->pvd_path().string());
  if (options.keep) {
    options.keep->world = std::move(world);
    options.keep->integrator = std::move(integrator_owner);
  }
  return code;
}

}  // namespace rkpm::sim
