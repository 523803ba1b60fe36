#include "rkpm/io/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>

namespace rkpm::io {

Progress::Progress(std::ostream& out, bool is_terminal) : out_(out), terminal_(is_terminal) {}

void Progress::update(std::int64_t step, double time, double t_end, double dt, double wall_elapsed,
                      const std::string& detail) {
  detail_ = detail;
  if (!started_) {
    time0_ = time;
    wall0_ = wall_elapsed;
  }
  step_ = step;
  time_ = time;
  t_end_ = t_end;
  dt_ = dt;
  wall_ = wall_elapsed;
  shown_ = false;
  finished_ = false;
  if (due(wall_elapsed)) print();
  started_ = true;
}

bool Progress::due(double wall_elapsed) const {
  if (!started_) return true;
  const double since = wall_elapsed - last_print_wall_;
  if (terminal_) return since >= kTerminalInterval;
  const bool next_decile = std::floor(percent() / kLogPercentStep) > std::floor(last_print_percent_ / kLogPercentStep);
  return next_decile || since >= kLogInterval;
}

double Progress::percent() const {
  if (!(t_end_ > 0.0)) return 100.0;
  return std::clamp(100.0 * time_ / t_end_, 0.0, 100.0);
}

double Progress::eta_seconds() const {
  const double advanced = time_ - time0_;
  const double spent = wall_ - wall0_;
  if (!(advanced > 0.0) || !(spent > 0.0)) return -1.0;
  return std::max(0.0, t_end_ - time_) * spent / advanced;
}

std::string Progress::line() const {
  const std::string detail = detail_.empty() ? std::string() : "  " + detail_;
  if (!(t_end_ > 0.0)) {
    // Open-ended (a relaxation): no end time, so no percentage and no ETA.
    return fmt::format("step {}  t = {:.4e} s  dt = {:.3e} s{}", step_, time_, dt_, detail);
  }
  const double eta = eta_seconds();
  return fmt::format("step {}  t = {:.4e} / {:.4e} s  ({:5.1f} %)  dt = {:.3e} s  ETA {}{}", step_, time_, t_end_,
                     percent(), dt_, eta < 0.0 ? std::string("--") : format_duration(eta), detail);
}

void Progress::print() {
  const std::string text = line();
  if (terminal_) {
    // Pad with blanks so a shorter line fully covers the previous one.
    const std::size_t pad = last_width_ > text.size() ? last_width_ - text.size() : 0;
    out_ << '\r' << text << std::string(pad, ' ') << std::flush;
    last_width_ = text.size();
  } else {
    out_ << text << '\n' << std::flush;
  }
  last_print_wall_ = wall_;
  last_print_percent_ = percent();
  shown_ = true;
}

void Progress::finish() {
  if (finished_ || !started_) return;
  if (!shown_) print();
  if (terminal_) out_ << '\n' << std::flush;
  finished_ = true;
}

std::string format_duration(double seconds) {
  const auto s = static_cast<long long>(std::llround(std::max(0.0, seconds)));
  if (s < 60) return fmt::format("{} s", s);
  if (s < 3600) return fmt::format("{} min {:02d} s", s / 60, s % 60);
  return fmt::format("{} h {:02d} min", s / 3600, (s % 3600) / 60);
}

bool stderr_is_terminal() { return ::isatty(::fileno(stderr)) != 0; }

}  // namespace rkpm::io
