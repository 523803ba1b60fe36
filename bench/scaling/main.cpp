// rkpm_scaling: particle-count scaling of set-up, step time and memory for three
// geometries (Mooney-Rivlin block, LCE sphere, RBC shell), with the machine's
// streaming bandwidth as the bound of the internal-force step. Run by
// `scripts/study scaling`; docs/verification/performance.md explains every column.
//
// The study re-runs this program for each size (--child) and for the machine's bounds,
// the triad and the arithmetic peak (--triad-only); those modes print machine-readable
// lines on stdout.
#include "measure_size.hpp"
#include "report.hpp"
#include "study.hpp"
#include "peak.hpp"
#include "triad.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <exception>
#include <new>

namespace {

using namespace rkpm;

int run_child(const std::string& geometry, int resolution, const scaling::MeasureSettings& m) {
  scaling::SizeResult r;
  r.geometry = geometry;
  r.resolution = resolution;
  try {
    const bench::Geometry g = bench::parse_geometry(geometry);
    r.particles = static_cast<double>(bench::particles_at(g, resolution));
    r = scaling::measure_size(g, resolution, m);
  } catch (const std::bad_alloc&) {
    r.status = "failed";
    r.note = "out of memory (std::bad_alloc)";
  } catch (const std::exception& e) {
    r.status = "failed";
    r.note = e.what();
    for (char& c : r.note)
      if (c == '\n') c = ' ';
  }
  fmt::print("{}\n", scaling::to_line(r));
  return r.status == "ok" ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Particle-count scaling study: set-up, step time, memory and bandwidth (docs/verification/performance.md)"};
  scaling::StudySettings study;
  std::string csv_path = "perf-scaling.csv", markdown_path = "perf-scaling.md";
  std::string command = "scripts/study scaling";
  std::vector<std::string> geometries = {"block", "sphere", "shell"};
  double memory_limit_gb = study.memory_limit_bytes / 1e9;
  scaling::RbcRelaxation rbc;
  std::string child_geometry;
  int child_resolution = 0, triad_mib = static_cast<int>(study.triad_array_bytes >> 20);
  bool triad_only = false, no_split = false;
  study.measure.rbc_scene = bench::source_file("examples/rbc/rbc.toml");

  app.add_option("--max", study.max_particles, "largest particle count of the ladder (1e3 .. max, geometric)");
  app.add_option("--min", study.min_particles, "smallest particle count");
  app.add_option("--sizes-per-decade", study.sizes_per_decade, "sizes per factor 10 in particle count")
      ->check(CLI::Range(1, 10));
  app.add_option("--geometries", geometries, "block, sphere, shell")->delimiter(',');
  app.add_option("--memory-limit-gb", memory_limit_gb, "skip sizes whose estimated peak memory exceeds this");
  app.add_option("--csv", csv_path, "CSV output");
  app.add_option("--markdown", markdown_path, "markdown output (tables and targets)");
  app.add_option("--command", command, "the command line quoted in the markdown");
  app.add_option("--rbc-scene", study.measure.rbc_scene, "the RBC scene whose face_cells are refined");
  app.add_option("--support-shape", study.measure.rk.support_shape,
                 "[body.rk] support_shape of every geometry's scene (the shell's example declares none)")
      ->check(CLI::IsMember({"sphere", "ellipsoid"}));
  app.add_option("--particle-order", study.measure.rk.particle_order, "[body.rk] particle_order of every geometry's scene")
      ->check(CLI::IsMember({"input", "morton"}));
  app.add_option("--gradient-precision", study.measure.rk.gradient_precision,
                 "[body.rk] gradient_precision of every geometry's scene")
      ->check(CLI::IsMember({"double", "float"}));
  app.add_option("--warmup", study.measure.warmup, "untimed steps before timing");
  app.add_option("--steps", study.measure.steps, "timed steps with 2 threads (median)");
  app.add_option("--steps-1t", study.measure.steps_1t, "timed steps with 1 thread (median)");
  app.add_flag("--no-split", no_split, "do not time the parts of build_world separately");
  app.add_option("--triad-mib", triad_mib, "size of each triad array [MiB]");
  app.add_option("--triad-repetitions", study.triad_repetitions, "triad repetitions (the best counts)");
  app.add_option("--setup-runs", study.setup_runs,
                 "processes measuring the set-up from 1e5 particles on (the median is kept)")
      ->check(CLI::Range(1, 9));
  app.add_option("--rbc-relaxation-wall", rbc.wall_s, "wall time of the default RBC relaxation [s] (from the script)");
  app.add_option("--rbc-relaxation-steps", rbc.steps, "its steps");
  app.add_option("--rbc-relaxation-status", rbc.status, "its status");
  // Internal modes (the study runs them in child processes).
  app.add_option("--child", child_geometry, "internal: measure one size of this geometry and print a RESULT line");
  app.add_option("--resolution", child_resolution, "internal: the resolution of --child");
  app.add_flag("--triad-only", triad_only, "internal: measure the triad and the arithmetic peak, print TRIAD and PEAK lines");
  CLI11_PARSE(app, argc, argv);
  study.measure.split = !no_split;
  study.memory_limit_bytes = memory_limit_gb * 1e9;
  study.triad_array_bytes = static_cast<std::size_t>(triad_mib) << 20;

  try {
    if (!child_geometry.empty()) return run_child(child_geometry, child_resolution, study.measure);
    if (triad_only) {
      const auto t = scaling::measure_triad(study.triad_array_bytes, 2, study.triad_repetitions);
      fmt::print("TRIAD gb_per_s={:.6g} array_bytes={} threads={} repetitions={}\n", t.gb_per_s, t.array_bytes,
                 t.threads, t.repetitions);
      const auto p = scaling::measure_peak(2, study.triad_repetitions);
      fmt::print("PEAK vector_gflops={:.6g} scalar_gflops={:.6g} vector_lanes={} isa={} threads={}\n",
                 p.vector_gflops, p.scalar_gflops, p.vector_lanes, p.isa, p.threads);
      return 0;
    }
    study.geometries.clear();
    for (const auto& g : geometries) study.geometries.push_back(bench::parse_geometry(g));
    const scaling::StudyResult result = scaling::run_study(study);
    scaling::write_csv(csv_path, result);
    scaling::write_markdown(markdown_path, result, rbc, command);
    fmt::print(stderr, "wrote {} and {}\n", csv_path, markdown_path);
  } catch (const std::exception& e) {
    fmt::print(stderr, "rkpm_scaling: {}\n", e.what());
    return 1;
  }
  return 0;
}
