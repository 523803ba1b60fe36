// rkpm: the command-line program.
//   rkpm run SCENE.toml [--out DIR] [--threads N] [--restart CHECKPOINT]
//   rkpm shape SCENE.toml FRAME.vtu|RUN_DIR [--body NAME] [--csv FILE]
//   rkpm check SCENE.toml [--out DIR] [--memory-limit SIZE]
//   rkpm params [--markdown]
#include "rkpm/par/comm.hpp"
#include "rkpm/scene/param_registry.hpp"
#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/run.hpp"
#include "rkpm/sim/compare_command.hpp"
#include "rkpm/sim/shape_command.hpp"

#include <CLI/CLI.hpp>
#include <omp.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <limits>
#include <thread>

#ifndef RKPM_VERSION
#define RKPM_VERSION "unknown"
#endif

namespace {

// The most OpenMP threads a run may ask for: the runtime's own limit, and at most 8 per
// hardware thread (more never speeds a step up, and thousands exhaust the threads or the
// stacks a process may have: libgomp then fails or crashes inside its thread start).
int thread_ceiling() {
  const long hardware = std::max(1u, std::thread::hardware_concurrency());
  return static_cast<int>(std::min<long>(omp_get_thread_limit(), 8 * hardware));
}

void report_internal_error(const std::string& what) {
  std::cerr << "error: internal error: " << what << " (please report it with the scene)\n";
}

// Ends every rank of a distributed run at once: the others may wait in a collective
// for the one that failed, and MPI_Finalize would wait for them.
void abort_if_distributed() {
  const auto& world = rkpm::par::Comm::world();
  if (world.parallel()) world.abort(rkpm::sim::kInternalError);
}

int command(int argc, char** argv) {
  CLI::App app{"rkpm: reproducing-kernel particle simulator for cell mechanics (active liquid-crystal "
               "elastomer cells on Mooney-Rivlin substrates)"};
  app.set_version_flag("--version", std::string("rkpm ") + RKPM_VERSION);
  app.require_subcommand(1);

  auto* run = app.add_subcommand("run", "Run a scene file; writes frames (VTU + PVD), checkpoints and summary.json");
  std::string scene_path, out_dir, restart;
  int threads = 0;
  std::string max_steps_text;
  bool quiet = false, allow_unstable = false;
  run->add_option("scene", scene_path, "Scene file (TOML)")->required();
  run->add_option("--out", out_dir, "Output directory (default: out/<scene name>)");
  run->add_option("--threads", threads, "OpenMP threads (default: all cores)")->check(CLI::NonNegativeNumber);
  run->add_option("--restart", restart, "Resume from a checkpoint written by an earlier run of the same scene");
  run->add_option("--max-steps", max_steps_text, "Stop after this many steps (a partial run; exit code 0)");
  run->add_flag("--quiet", quiet, "No progress line");
  std::string memory_limit;
  bool dry_run = false;
  run->add_option("--memory-limit", memory_limit,
                  "Refuse a scene whose estimated memory exceeds this (e.g. 8G; default: what the machine has)");
  run->add_flag("--dry-run", dry_run, "Print what the scene will cost (as `rkpm check`) and stop");
  run->add_flag("--allow-unstable-dt", allow_unstable,
                "Keep a requested dt above the stable estimate (for testing the blow-up diagnosis)");

  auto* shape = app.add_subcommand("shape", "Shape report (thickness profile, Evans-Fung comparison) of a frame of a run");
  rkpm::sim::ShapeCommandOptions shape_options;
  std::string shape_scene, shape_frame, shape_csv;
  shape->add_option("scene", shape_scene, "Scene file (TOML) of the run")->required();
  shape->add_option("frame", shape_frame, "A .vtu frame, or the run's output directory (its last frame)")->required();
  shape->add_option("--body", shape_options.body, "Shell body to measure (default: [output] shape_report)");
  shape->add_option("--csv", shape_csv, "Profile CSV to write (default: shape_profile.csv beside the frame)");

  auto* compare = app.add_subcommand(
      "compare", "How far apart two runs of a scene end: the largest particle distance between their frames");
  rkpm::sim::CompareCommandOptions compare_options;
  compare->add_option("reference", compare_options.reference, "A .vtu/.pvtu frame, or a run's output directory")
      ->required();
  compare->add_option("other", compare_options.other, "The frame (or run directory) to compare with it")->required();

  auto* check = app.add_subcommand(
      "check", "Validate a scene and print what it will cost: particles, operator entries, memory, output size");
  check->add_option("scene", scene_path, "Scene file (TOML)")->required();
  check->add_option("--out", out_dir, "Output directory whose free space is checked (default: out/<scene name>)");
  check->add_option("--memory-limit", memory_limit, "Memory the run may use (e.g. 8G; default: what the machine has)");

  auto* params = app.add_subcommand("params", "Print every scene parameter: section, key, type, unit, default, range, help");
  bool markdown = false;
  params->add_flag("--markdown", markdown, "Markdown table (the README's parameter reference)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : rkpm::sim::kBadInput;
  }

  if (*params) {
    rkpm::scene::print_params(std::cout, markdown ? rkpm::scene::ParamFormat::markdown : rkpm::scene::ParamFormat::text);
    return 0;
  }

  if (*shape) {
    shape_options.scene = shape_scene;
    shape_options.frame = shape_frame;
    shape_options.csv = shape_csv;
    return rkpm::sim::run_shape_command(shape_options, std::cout, std::cerr);
  }

  if (*compare) return rkpm::sim::run_compare_command(compare_options, std::cout, std::cerr);

  rkpm::scene::Scene scene;
  try {
    scene = rkpm::scene::load_scene(scene_path);
  } catch (const rkpm::scene::SceneError& e) {
    // Every rank reads the same file and finds the same error: rank 0 reports it.
    if (rkpm::par::Comm::world().root()) std::cerr << "error: " << e.what() << "\n";
    return rkpm::sim::kBadInput;
  }
  // Read as text and converted here: CLI11 would saturate a number beyond the integer
  // range instead of refusing it.
  std::int64_t max_steps = 0;
  if (!max_steps_text.empty()) {
    const char* end = max_steps_text.data() + max_steps_text.size();
    const auto [stop, error] = std::from_chars(max_steps_text.data(), end, max_steps);
    if (error != std::errc() || stop != end || max_steps < 0) {
      if (rkpm::par::Comm::world().root())
        std::cerr << "error: --max-steps " << max_steps_text << ": expected a whole number from 0 to "
                  << std::numeric_limits<std::int64_t>::max() << "\n";
      return rkpm::sim::kBadInput;
    }
  }
  // The smallest ceiling over the ranks, so that every rank gives the same verdict.
  const int ceiling = static_cast<int>(rkpm::par::Comm::world().min(static_cast<double>(thread_ceiling())));
  if (threads > ceiling) {
    if (rkpm::par::Comm::world().root())
      std::cerr << "error: --threads " << threads << ": more than this machine allows (at most " << ceiling
                << ": 8 per hardware thread, within the OpenMP thread limit)\n";
    return rkpm::sim::kBadInput;
  }
  if (threads > 0) omp_set_num_threads(threads);
  rkpm::sim::RunOptions options;
  options.out_dir = out_dir.empty() ? std::filesystem::path("out") / scene.scene.text("name") : std::filesystem::path(out_dir);
  options.restart = restart;
  options.max_steps_override = max_steps;
  options.quiet = quiet;
  options.allow_unstable_dt = allow_unstable;
  try {
    if (!memory_limit.empty()) options.limits.memory_bytes = rkpm::sim::parse_byte_size(memory_limit);
  } catch (const std::invalid_argument& e) {
    if (rkpm::par::Comm::world().root()) std::cerr << "error: " << e.what() << "\n";
    return rkpm::sim::kBadInput;
  }
  if (*check || dry_run) {
    // The estimate, then the verdict a run would give: 0 when it fits, 2 when it would be
    // refused. Under mpirun every rank finds the same and rank 0 prints it.
    const bool speaks = rkpm::par::Comm::world().root();
    std::ostream silent(nullptr);
    std::ostream& out = speaks ? std::cout : silent;
    std::ostream& err = speaks ? std::cerr : silent;
    const auto& world = rkpm::par::Comm::world();
    try {
      const auto estimate = rkpm::sim::estimate_run(scene, world.size(), world.node_size());
      rkpm::sim::print_estimate(out, scene, estimate, options.limits, options.out_dir);
      // Without a set-up the step is unknown: the disk must hold at least the first and last frames.
      rkpm::sim::check_memory(estimate, options.limits);
      rkpm::sim::check_disk(scene, estimate, rkpm::sim::frames_expected(scene, estimate, std::nullopt), options.limits,
                            options.out_dir);
    } catch (const rkpm::sim::PreflightError& e) {
      err << "error: " << e.what() << "\n";
      return rkpm::sim::kBadInput;
    }
    out << "fits: a run of this scene is not refused for its size\n";
    return rkpm::sim::kSuccess;
  }
  try {
    return rkpm::sim::run_scene(scene, options, std::cerr);
  } catch (const std::exception& e) {
    // Found on this rank alone: the others may wait for it in a collective, so a
    // distributed run ends every rank at once.
    const auto& comm = rkpm::par::Comm::world();
    std::cerr << "error" << (comm.parallel() ? " (rank " + std::to_string(comm.rank()) + ")" : "") << ": " << e.what() << "\n";
    if (comm.parallel()) comm.abort(rkpm::sim::kInternalError);
    return rkpm::sim::kInternalError;
  }
}

// The last words of a process that met an exception nothing else caught (one thrown on
// an OpenMP thread cannot reach main's handlers): a message and exit 1, never
// std::terminate's abort.
[[noreturn]] void last_words() {
  try {
    if (const auto e = std::current_exception()) std::rethrow_exception(e);
    report_internal_error("terminated without an exception");
  } catch (const std::exception& e) {
    report_internal_error(e.what());
  } catch (...) {
    report_internal_error("an exception of unknown type");
  }
  abort_if_distributed();
  std::_Exit(rkpm::sim::kInternalError);
}

}  // namespace

int main(int argc, char** argv) {
  std::set_terminate(last_words);
  rkpm::par::Session mpi(argc, argv);  // joins the run's ranks under mpirun; nothing otherwise
  try {
    return command(argc, argv);
  } catch (const std::exception& e) {
    report_internal_error(e.what());
  } catch (...) {
    report_internal_error("an exception of unknown type");
  }
  abort_if_distributed();
  return rkpm::sim::kInternalError;
}
