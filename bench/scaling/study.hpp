// The particle-count study: a geometric ladder of sizes per geometry, each size in
// its own child process, plus the triad in one more.
#pragma once

#include "../common/scenes.hpp"
#include "measure_size.hpp"
#include "peak.hpp"
#include "record.hpp"
#include "triad.hpp"

#include <vector>

namespace rkpm::scaling {

struct StudySettings {
  double min_particles = 1e3;
  double max_particles = 1e6;
  int sizes_per_decade = 2;  // 1e3..1e6: 7 sizes
  std::vector<bench::Geometry> geometries = {bench::Geometry::Block, bench::Geometry::Sphere, bench::Geometry::Shell};
  double memory_limit_bytes = 16e9;  // sizes estimated above this (or above 90 % of MemAvailable) are skipped
  MeasureSettings measure;
  std::size_t triad_array_bytes = std::size_t{256} << 20;
  int triad_repetitions = 10;
  // From setup_exponent_from (report.hpp's Targets) on, the set-up is measured in this
  // many processes and the median kept: one run's set-up varies by about 5 % on a shared
  // machine, which moves an exponent fitted over one decade by 0.02.
  int setup_runs = 3;
};

struct StudyResult {
  TriadResult triad;
  PeakResult peak;                 // the roofline's other ceiling
  std::vector<SizeResult> sizes;  // geometry by geometry, small to large
  bench::RkChoices rk;             // the [body.rk] keys the scenes declared
};

StudyResult run_study(const StudySettings& settings);

// The child-process arguments for one size, and for the triad.
std::vector<std::string> child_arguments(bench::Geometry g, int resolution, const MeasureSettings& m);
std::vector<std::string> triad_arguments(const StudySettings& s);

}  // namespace rkpm::scaling
