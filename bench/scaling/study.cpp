#include "study.hpp"

#include "memory.hpp"
#include "report.hpp"
#include "subprocess.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rkpm::scaling {

namespace {

// Bytes per particle assumed for a geometry's first size, before any measurement
// (the smallest sizes are tiny whatever it is).
constexpr double kDefaultBytesPerParticle = 8192.0;
// Margin on the extrapolated peak: per-particle memory grows slowly with N
// (operator rows lengthen near refined rims, allocator slack).
constexpr double kEstimateMargin = 1.25;

std::vector<double> ladder(const StudySettings& s) {
  std::vector<double> targets;
  const double step = std::pow(10.0, 1.0 / s.sizes_per_decade);
  for (double t = s.min_particles; t <= s.max_particles * 1.0001; t *= step) targets.push_back(t);
  return targets;
}

// The key=value words of the output's line that starts with `tag`, handed to set(key, value).
template <class Set>
void parse_line(const std::string& output, const std::string& tag, const Set& set) {
  std::istringstream lines(output);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind(tag + " ", 0) != 0) continue;
    std::istringstream words(line.substr(tag.size() + 1));
    std::string w;
    while (words >> w) {
      const auto eq = w.find('=');
      if (eq != std::string::npos) set(w.substr(0, eq), w.substr(eq + 1));
    }
  }
}

TriadResult parse_triad(const std::string& output) {
  TriadResult t;
  parse_line(output, "TRIAD", [&](const std::string& key, const std::string& value) {
    if (key == "gb_per_s") t.gb_per_s = std::stod(value);
    if (key == "array_bytes") t.array_bytes = static_cast<std::size_t>(std::stod(value));
    if (key == "threads") t.threads = std::stoi(value);
    if (key == "repetitions") t.repetitions = std::stoi(value);
  });
  return t;
}

PeakResult parse_peak(const std::string& output) {
  PeakResult p;
  parse_line(output, "PEAK", [&](const std::string& key, const std::string& value) {
    if (key == "vector_gflops") p.vector_gflops = std::stod(value);
    if (key == "scalar_gflops") p.scalar_gflops = std::stod(value);
    if (key == "vector_lanes") p.vector_lanes = std::stoi(value);
    if (key == "isa") p.isa = value;
    if (key == "threads") p.threads = std::stoi(value);
  });
  return p;
}

// The RESULT line of a child's output, read into r; false if it printed none.
bool read_result(const ChildOutcome& child, SizeResult& r) {
  bool found = false;
  std::istringstream lines(child.output);
  std::string line;
  while (std::getline(lines, line)) found = from_line(line, r) || found;
  return found;
}

// Replaces r's set-up (build_world and initialize) by the median of s.setup_runs
// processes, r's own run included; the others only set up (no split, no steps). The
// parts timed one by one stay r's own, and so does the build_world they are part of
// (split_run_setup_s). The median of an even count is the mean of the middle two runs.
void median_setup(bench::Geometry g, int resolution, const StudySettings& s, SizeResult& r) {
  MeasureSettings setup_only = s.measure;
  setup_only.split = false;
  setup_only.warmup = setup_only.steps = setup_only.steps_1t = 0;
  r.split_run_setup_s = r.setup_s;
  std::vector<std::pair<double, double>> runs{{r.setup_s, r.init_s}};
  for (int k = 1; k < s.setup_runs; ++k) {
    const ChildOutcome child = run_self(child_arguments(g, resolution, setup_only));
    SizeResult again;
    if (read_result(child, again) && child.ok && again.status == "ok")
      runs.emplace_back(again.setup_s, again.init_s);
    else
      fmt::print(stderr, "{} {} particles: a repeated set-up failed ({}); left out of the median\n", r.geometry,
                 r.particles, child.status);
  }
  std::sort(runs.begin(), runs.end(),
            [](const auto& a, const auto& b) { return a.first + a.second < b.first + b.second; });
  const auto& low = runs[(runs.size() - 1) / 2];
  const auto& high = runs[runs.size() / 2];
  r.setup_s = 0.5 * (low.first + high.first);
  r.init_s = 0.5 * (low.second + high.second);
  r.setup_runs = static_cast<double>(runs.size());
  fmt::print(stderr, "{} {} particles: set-up {} runs, median {:.3f} s\n", r.geometry, r.particles, runs.size(),
             r.setup_s + r.init_s);
}

}  // namespace

std::vector<std::string> child_arguments(bench::Geometry g, int resolution, const MeasureSettings& m) {
  std::vector<std::string> a = {"--child",   bench::geometry_name(g), "--resolution", std::to_string(resolution),
                                "--warmup",  std::to_string(m.warmup), "--steps",     std::to_string(m.steps),
                                "--steps-1t", std::to_string(m.steps_1t), "--rbc-scene", m.rbc_scene,
                                "--support-shape", m.rk.support_shape, "--particle-order", m.rk.particle_order,
                                "--gradient-precision", m.rk.gradient_precision};
  if (!m.split) a.emplace_back("--no-split");
  return a;
}

std::vector<std::string> triad_arguments(const StudySettings& s) {
  return {"--triad-only", "--triad-mib", std::to_string(s.triad_array_bytes >> 20), "--triad-repetitions",
          std::to_string(s.triad_repetitions)};
}

StudyResult run_study(const StudySettings& s) {
  StudyResult study;
  study.rk = s.measure.rk;
  fmt::print(stderr, "triad: 3 arrays of {} MiB, 2 threads, best of {}\n", s.triad_array_bytes >> 20,
             s.triad_repetitions);
  const ChildOutcome triad = run_self(triad_arguments(s));
  study.triad = parse_triad(triad.output);
  study.peak = parse_peak(triad.output);
  if (!triad.ok || study.triad.gb_per_s <= 0.0) fmt::print(stderr, "triad failed: {}\n", triad.status);
  else
    fmt::print(stderr, "triad: {:.2f} GB/s; peak {:.1f} GFLOP/s ({}, {} lanes), scalar {:.1f}\n", study.triad.gb_per_s,
               study.peak.vector_gflops, study.peak.isa, study.peak.vector_lanes, study.peak.scalar_gflops);

  for (const bench::Geometry g : s.geometries) {
    double bytes_per_particle = kDefaultBytesPerParticle;
    std::string failed_smaller;
    for (const double target : ladder(s)) {
      const int resolution = bench::resolution_for(g, target);
      SizeResult r;
      r.geometry = bench::geometry_name(g);
      r.resolution = resolution;
      r.particles = static_cast<double>(bench::particles_at(g, resolution));
      // A size that a smaller one could not do, or that would not fit, is not started.
      const double estimate = kEstimateMargin * bytes_per_particle * r.particles;
      const std::size_t available = available_bytes();
      const double limit =
          available > 0 ? std::min(s.memory_limit_bytes, 0.9 * static_cast<double>(available)) : s.memory_limit_bytes;
      if (!failed_smaller.empty()) {
        r.status = "skipped";
        r.note = "a smaller size failed (" + failed_smaller + ")";
      } else if (estimate > limit) {
        r.status = "skipped";
        r.note = fmt::format("estimated peak {:.3g} GB > limit {:.3g} GB", estimate / 1e9, limit / 1e9);
      } else {
        fmt::print(stderr, "{} resolution {} ({} particles): running\n", r.geometry, resolution, r.particles);
        const ChildOutcome child = run_self(child_arguments(g, resolution, s.measure));
        SizeResult measured;
        const bool found = read_result(child, measured);
        if (child.ok && found) {
          r = measured;
          if (r.particles > 0 && r.peak_bytes > 0) bytes_per_particle = r.peak_bytes / r.particles;
          if (r.particles >= Targets{}.setup_exponent_from) median_setup(g, resolution, s, r);
        } else {
          r.status = "failed";
          r.note = found && !measured.note.empty() ? measured.note : child.status;
          failed_smaller = fmt::format("{} particles: {}", r.particles, r.note);
        }
      }
      fmt::print(stderr, "{} {} particles: {}{}{}\n", r.geometry, r.particles, r.status, r.note.empty() ? "" : ": ",
                 r.note);
      study.sizes.push_back(r);
    }
  }
  return study;
}

}  // namespace rkpm::scaling
