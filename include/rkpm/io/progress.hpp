// Progress line for the command-line program.
//
// On a terminal one line is rewritten in place ('\r') at most 5 times per
// second. Otherwise (log files, CI) a plain line is printed at most at every
// 10 % of simulated time or every 30 s of wall time, whichever comes first, so
// a long run adds a few dozen lines to a log, not millions.
//
// The wall clock is an argument of update(), measured by the caller (which
// needs it for summary.json anyway); tests drive it with made-up times.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>

namespace rkpm::io {

class Progress {
 public:
  static constexpr double kTerminalInterval = 0.2;  // [s] wall time between rewrites on a terminal
  static constexpr double kLogInterval = 30.0;      // [s] wall time between log lines at most
  static constexpr double kLogPercentStep = 10.0;   // [%] progress between log lines at most

  Progress(std::ostream& out, bool is_terminal);

  // Reports the state after `step`: simulated `time` of `t_end`, current
  // time step `dt`, and `wall_elapsed` seconds since the run started.
  // t_end <= 0 marks an open-ended run (a relaxation): no percentage, no ETA. `detail`
  // is appended to the line (e.g. the relaxation residual).
  void update(std::int64_t step, double time, double t_end, double dt, double wall_elapsed,
              const std::string& detail = "");
  // Prints the last state if it was not shown yet and ends the line. Idempotent.
  void finish();

  // The text of one progress line (no '\r' or newline), exposed for tests.
  std::string line() const;

 private:
  bool due(double wall_elapsed) const;
  void print();
  double percent() const;
  double eta_seconds() const;  // < 0 when not yet estimable

  std::ostream& out_;
  bool terminal_;
  bool started_ = false;
  bool shown_ = true;  // the latest state has been printed
  bool finished_ = false;
  std::size_t last_width_ = 0;
  // Latest state.
  std::int64_t step_ = 0;
  std::string detail_;
  double time_ = 0.0, t_end_ = 0.0, dt_ = 0.0, wall_ = 0.0;
  // First update, for the rate behind the ETA (a restarted run starts at t > 0).
  double time0_ = 0.0, wall0_ = 0.0;
  // Last printed line.
  double last_print_wall_ = 0.0, last_print_percent_ = 0.0;
};

// "45 s", "12 min 03 s", "3 h 05 min".
std::string format_duration(double seconds);

// True when standard error is an interactive terminal.
bool stderr_is_terminal();

}  // namespace rkpm::io
