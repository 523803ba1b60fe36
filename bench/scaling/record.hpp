// What one size of one geometry measured: written by the child process that ran it
// as a single "RESULT key=value ..." line on stdout, read back by the study.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace rkpm::scaling {

struct SizeResult {
  std::string geometry;
  std::string status = "ok";  // ok | skipped | failed
  std::string note;           // why skipped or failed
  double resolution = 0;      // block, sphere: cells; shell: face_cells
  double particles = 0;

  // Set-up [s]: build_world in full, Integrator::initialize, and the parts of
  // build_world timed again one by one on the same scene (0 when --no-split).
  double setup_s = 0, init_s = 0;
  double cloud_s = 0, tree_s = 0, gradient_s = 0, interpolation_s = 0, boundary_s = 0;
  double query_s = 0;  // one radius query per particle (inside interpolation_s)
  double setup_runs = 1;  // processes whose set-up was measured: setup_s and init_s are their median
  double split_run_setup_s = 0;  // build_world in the run whose parts were timed (the median may be another's)

  // Medians over the timed steps [s].
  double step_2t_s = 0, step_1t_s = 0;    // Integrator::step, 2 and 1 threads
  double force_2t_s = 0, force_1t_s = 0;  // compute_internal_forces over all bodies
  double steps_timed = 0;

  // Memory [bytes]: peak RSS of the child above its baseline at start; the Body arrays.
  double peak_bytes = 0, baseline_bytes = 0;
  double operators_bytes = 0, state_bytes = 0, cloud_bytes = 0;
  double traffic_bytes = 0;  // internal-force step, footprint.hpp
  double force_flops = 0;    // its floating-point operations, footprint.hpp (a lower bound)

  // Row lengths (entries per row) of the gradient operator over all bodies: mean, 95th
  // percentile, largest; and the interpolation operator's mean.
  double gradient_row_mean = 0, gradient_row_p95 = 0, gradient_row_max = 0;
  double interpolation_row_mean = 0;

  double other_setup_s() const;  // build_world minus the parts timed separately
};

// The numeric fields with their CSV / protocol names, in column order.
const std::vector<std::pair<const char*, double SizeResult::*>>& numeric_fields();

std::string to_line(const SizeResult& r);        // "RESULT geometry=... key=value ... note=..."
bool from_line(const std::string& line, SizeResult& r);  // false if not a RESULT line

}  // namespace rkpm::scaling
