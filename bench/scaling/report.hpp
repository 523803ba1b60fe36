// The study's outputs: a CSV with every measured number (docs/figures/perf-scaling.csv)
// and the markdown tables and target list of docs/verification/performance.md.
#pragma once

#include "study.hpp"

#include <string>

namespace rkpm::scaling {

// The default RBC relaxation (examples/rbc/rbc.toml run to convergence by `rkpm run`),
// measured by the script; wall_s < 0: not measured in this run.
struct RbcRelaxation {
  double wall_s = -1.0;
  long long steps = 0;
  std::string status;
};

// Peak RSS per particle a geometry may take: at the largest size, or (a thin shell,
// whose rows once grew with refinement) at every size from `from_particles` up.
struct MemoryTarget {
  double bytes_per_particle = 0.0;
  double from_particles = 0.0;  // 0: judged at the largest size only
};

struct Targets {
  double bandwidth_fraction = 0.5;  // internal-force step, of the triad bound
  double step_exponent = 1.05;      // from 1e3 to 1e6 particles
  double setup_s_per_100k = 2.0;
  double setup_exponent = 1.02;     // from 1e5 to 1e6 particles, where a growing search shows
  double setup_exponent_from = 0.9e5;
  double rbc_relaxation_s = 15.0;
  // Block 2 KB, sphere 3 KB, shell 4 KB, read as thousands of bytes (the stricter).
  static MemoryTarget memory(const std::string& geometry) {
    if (geometry == "shell") return {4000.0, 1e4};
    if (geometry == "sphere") return {3000.0, 0.0};
    return {2000.0, 0.0};
  }
};

void write_csv(const std::string& path, const StudyResult& study);
void write_markdown(const std::string& path, const StudyResult& study, const RbcRelaxation& rbc,
                    const std::string& command);

// Derived quantities, shared by both outputs.
double bandwidth_fraction(const SizeResult& r, const TriadResult& triad);  // NaN when not measurable
// The roofline (docs/verification/performance.md): the internal force's arithmetic
// intensity [flop/B], its rate [1e9 flop/s], and the least time the two ceilings allow
// it, bytes / triad or flops / vector peak, whichever is longer [s]; NaN when not measurable.
double intensity(const SizeResult& r);
double gflops(const SizeResult& r);
double roofline_s(const SizeResult& r, const TriadResult& triad, const PeakResult& peak);
double setup_total_s(const SizeResult& r);                                   // build_world + initialize

}  // namespace rkpm::scaling
