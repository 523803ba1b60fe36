// run_scene: its phases in order (run_phases.hpp) around the time loop, which is here:
// steps, frames, checkpoints and the progress line, then the relaxation's Newton-Krylov
// finish if the scene asks for it.
#include "rkpm/sim/run.hpp"

#include "sim/run/collective_output.hpp"
#include "sim/run/run_loop.hpp"
#include "sim/run/run_phases.hpp"

#include "rkpm/io/vtu_writer.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <ostream>

namespace rkpm::sim {

std::string relax_progress(const Integrator& integrator, const IntegratorSettings& settings) {
  std::string line = fmt::format("residual {:.2e} (target {:.0e}), kinetic {:.1e} (target {:.0e})",
                                 integrator.residual(), settings.relax_force_tol, integrator.kinetic_measure(),
                                 settings.relax_velocity_tol);
  if (settings.relax_state_tol > 0.0)
    line += fmt::format(", state {:.1e} (target {:.0e})", integrator.state_measure(), settings.relax_state_tol);
  return line;
}

namespace {

double scene_t_end(const scene::Scene& scene) {
  return scene.integrator.has("t_end") ? scene.integrator.real("t_end") : INFINITY;
}

}  // namespace

RunLoop::RunLoop(const scene::Scene& scene, const RunOptions& options, World& world, Integrator& integrator,
                 const IntegratorSettings& settings, RunOutput& output, RunClock& clock, std::ostream& log,
                 std::function<double()> elapsed)
    : options_(options),
      world_(world),
      integrator_(integrator),
      settings_(settings),
      output_(output),
      clock_(clock),
      log_(log),
      elapsed_(std::move(elapsed)),
      relax_(settings.mode == Mode::Relax),
      t_end_(scene_t_end(scene)),
      every_(scene.output.has("every") ? scene.output.real("every") : t_end_ / 50.0),
      checkpoint_every_(scene.output.integer("checkpoint_every")),
      max_steps_(scene.integrator.integer("max_steps")),
      digest_(file_digest(scene.file)),
      checkpoint_path_(rank_file(options.out_dir / "checkpoint.bin", *options.comm)),
      progress_(log, !options.quiet && io::stderr_is_terminal()) {}

void RunLoop::write_frame() {
  output_.write_frame(world_, integrator_);
  ++clock_.frames;
}

LoopEnd RunLoop::run() {
  LoopEnd end;
  try {
    if (options_.restart.empty()) {
      write_frame();
      clock_.next_output = every_;
    }
    step_until_done(end);
    if (relax_ && settings_.newton_krylov_finish && end.code == kSuccess && end.status == "completed")
      finish_newton_krylov(end);
    // The final state is always in the series.
    if (!output_.has_frame_at(world_.time)) write_frame();
  } catch (const BlowUp& e) {
    end.status = "unstable";
    end.diagnosis = e.what();
    end.code = kUnstable;
  } catch (const io::NonFiniteValue& e) {
    end.status = "unstable";
    end.diagnosis = fmt::format("a non-finite value reached the output at step {} (t = {:.6g} s): {}", world_.step,
                                world_.time, e.what());
    end.code = kUnstable;
  } catch (const OutputFailed& e) {
    end.status = "output failed";
    end.diagnosis = fmt::format("writing the output failed at step {} (t = {:.6g} s): {}", world_.step,
                                world_.time, e.what());
    end.code = kOutputFailed;
  }
  if (!options_.quiet) progress_.finish();
  return end;
}

void RunLoop::step_until_done(LoopEnd& end) {
  const par::Comm& comm = *options_.comm;
  while (true) {
    const bool time_is_up = world_.time >= t_end_ * (1.0 - 1e-12);
    if (relax_ ? (world_.step > 0 && integrator_.converged()) : time_is_up) return;
    if (options_.max_steps_override > 0 && world_.step >= options_.max_steps_override) {
      end.status = "stopped at --max-steps";  // asked for on the command line: not a failure
      return;
    }
    if (world_.step >= max_steps_ || (relax_ && time_is_up)) {
      end.status = relax_ ? "not converged" : "max_steps reached before t_end";
      end.code = kIncomplete;
      return;
    }
    integrator_.step();
    // A step that ends FIRE before a finish leaves its frame to the finished state
    // (a frame at the same time cannot follow it).
    const bool finish_follows = relax_ && settings_.newton_krylov_finish && integrator_.converged();
    if (!finish_follows && world_.time >= clock_.next_output * (1.0 - 1e-12)) {
      write_frame();
      clock_.next_output += every_;
    }
    if (checkpoint_every_ > 0 && world_.step % checkpoint_every_ == 0)
      collective_output(comm, [&] { write_checkpoint(checkpoint_path_, world_, integrator_, clock_, digest_); });
    if (!options_.quiet)
      progress_.update(world_.step, world_.time, relax_ ? 0.0 : t_end_, integrator_.dt(), elapsed_(),
                       relax_ ? relax_progress(integrator_, settings_) : std::string());
    // Every rank stops at the same step when one caller asks (Ctrl-C reaches the ranks
    // at different steps), or the ranks' collectives would no longer match.
    if (options_.after_step && comm.min(options_.after_step(world_, integrator_) ? 1.0 : 0.0) == 0.0) {
      end.status = "interrupted";
      end.code = kIncomplete;
      return;
    }
  }
}

void RunLoop::finish_newton_krylov(LoopEnd& end) {
  if (!options_.quiet) progress_.finish();
  const std::int64_t evaluations_before = integrator_.force_evaluations();
  // One line per Newton step (a handful to a few dozen): what a long finish is doing.
  std::function<void(const NewtonKrylovReport&)> report_step;
  if (!options_.quiet) report_step = [&](const NewtonKrylovReport& so_far) {
    log_ << fmt::format("newton-krylov step {}: residual {:.2e} (target {:.0e}), {} GMRES iterations and {} "
                        "force evaluations so far, {:.1f} s\n",
                        so_far.newton_steps, so_far.residual, settings_.newton.force_tol, so_far.krylov_iterations,
                        so_far.force_evaluations, elapsed_());
    log_.flush();
  };
  end.finish = integrator_.finish_newton_krylov(settings_.newton, report_step);
  log_ << fmt::format("newton-krylov: {} after {} Newton steps, {} GMRES iterations, {} force evaluations; "
                      "residual {:.2e} (target {:.0e})\n",
                      end.finish->stop, end.finish->newton_steps, end.finish->krylov_iterations,
                      integrator_.force_evaluations() - evaluations_before, end.finish->residual,
                      settings_.newton.force_tol);
  if (!end.finish->converged) {
    end.status = "not converged";
    end.code = kIncomplete;
  }
}

int run_scene(const scene::Scene& scene, const RunOptions& options, std::ostream& root_log) {
  const par::Comm& comm = *options.comm;
  std::ostream silent(nullptr);  // the other ranks' messages: rank 0 speaks for the run
  std::ostream& log = comm.root() ? root_log : silent;
  const auto wall_start = std::chrono::steady_clock::now();
  const std::function<double()> elapsed = [wall_start] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  };

  RunSetup s;
  std::vector<LevelRun> levels;
  RunClock clock;
  std::unique_ptr<RunOutput> output;
  try {
    s = set_up(scene, options, log);
    // A restart resumes the fine run itself.
    if (options.restart.empty()) levels = relax_levels(scene, s, options, log, elapsed);
    start(scene, s, options);
    output = open_output(scene, s, options, clock);
  } catch (const RunRefused& refused) {
    log << "error: " << refused.message << "\n";
    return refused.code;
  }
  report_step_size(s, log);

  RunLoop loop(scene, options, *s.world, *s.integrator, s.settings, *output, clock, log, elapsed);
  const LoopEnd end = loop.run();
  const int code = conclude(scene, s, options, levels, end, *output, elapsed(), log);
  if (options.keep) {
    options.keep->world = std::move(s.world);
    options.keep->integrator = std::move(s.integrator);
  }
  return code;
}

}  // namespace rkpm::sim
