// The progress line is throttled: at most 5 rewrites per second of wall time
// on a terminal; in logs, a line per 10 % of progress or per 30 s of wall time.
#include "rkpm/io/progress.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

namespace rkpm::io {
namespace {

// Drives `steps` uniform steps of a run to t_end = 1 with an injected wall clock that
// reads `wall_total` seconds at the end: the throttling rule is tested on given clock
// values, and no real time is measured or asserted.
std::string run(bool terminal, int steps, double wall_total) {
  std::ostringstream out;
  Progress progress(out, terminal);
  for (int k = 1; k <= steps; ++k) {
    progress.update(k, static_cast<double>(k) / steps, 1.0, 1.0 / steps, wall_total * k / steps);
  }
  progress.finish();
  return out.str();
}

long count(const std::string& s, char c) { return std::count(s.begin(), s.end(), c); }

TEST(Progress, TerminalRewritesAtMostFiveTimesPerSecond) {
  const std::string out = run(true, 10000, 10.0);  // 1000 updates per wall second
  const long rewrites = count(out, '\r');
  EXPECT_LE(rewrites, static_cast<long>(10.0 / Progress::kTerminalInterval) + 2);
  EXPECT_GE(rewrites, static_cast<long>(10.0 / Progress::kTerminalInterval) - 2);
  EXPECT_EQ(count(out, '\n'), 1);  // finish() ends the single line
  EXPECT_EQ(out.back(), '\n');
  // The last rewrite shows the final state.
  const std::string last = out.substr(out.rfind('\r') + 1);
  EXPECT_NE(last.find("step 10000"), std::string::npos) << last;
  EXPECT_NE(last.find("100.0 %"), std::string::npos) << last;
}

TEST(Progress, TerminalShowsEveryUpdateWhenTheyAreSlow) {
  const std::string out = run(true, 20, 20.0);  // one update per wall second
  EXPECT_EQ(count(out, '\r'), 20);
}

TEST(Progress, LogPrintsOncePerTenPercentOnFastRuns) {
  const std::string out = run(false, 10000, 10.0);
  EXPECT_EQ(count(out, '\r'), 0);
  // First update, then one line at each of 10 %, 20 %, ..., 100 %.
  EXPECT_EQ(count(out, '\n'), 11) << out;
}

TEST(Progress, LogPrintsEveryThirtySecondsOnSlowRuns) {
  const double injected_wall = 3000.0;  // the fake clock advances 3 s per step over 1000 steps
  const std::string out = run(false, 1000, injected_wall);
  const long lines = count(out, '\n');
  // Never more often than the 30 s rule plus the 10 % lines, never silent for 30 s.
  const long intervals = static_cast<long>(injected_wall / Progress::kLogInterval);
  EXPECT_LE(lines, intervals + 11) << out;
  EXPECT_GE(lines, intervals) << out;
}

TEST(Progress, FinishPrintsAnUnshownFinalStateOnce) {
  std::ostringstream out;
  Progress progress(out, false);
  progress.update(1, 0.01, 1.0, 0.01, 0.1);
  progress.update(2, 0.02, 1.0, 0.01, 0.2);  // throttled
  EXPECT_EQ(count(out.str(), '\n'), 1);
  progress.finish();
  progress.finish();
  EXPECT_EQ(count(out.str(), '\n'), 2);
  EXPECT_NE(out.str().find("step 2 "), std::string::npos) << out.str();
}

TEST(Progress, LineShowsStepTimeDtPercentAndEta) {
  std::ostringstream out;
  Progress progress(out, false);
  progress.update(100, 0.1, 1.0, 1e-3, 1.0);
  progress.update(500, 0.5, 1.0, 2e-3, 9.0);  // 0.4 s simulated in 8 s wall: 0.5 s left takes 10 s
  const std::string line = progress.line();
  EXPECT_NE(line.find("step 500"), std::string::npos) << line;
  EXPECT_NE(line.find("t = 5.0000e-01 / 1.0000e+00 s"), std::string::npos) << line;
  EXPECT_NE(line.find(" 50.0 %"), std::string::npos) << line;
  EXPECT_NE(line.find("dt = 2.000e-03 s"), std::string::npos) << line;
  EXPECT_NE(line.find("ETA 10 s"), std::string::npos) << line;
}

TEST(Progress, EtaUnknownBeforeAnyProgress) {
  std::ostringstream out;
  Progress progress(out, true);
  progress.update(0, 0.0, 1.0, 1e-3, 0.0);
  EXPECT_NE(progress.line().find("ETA --"), std::string::npos) << progress.line();
}

TEST(Progress, DurationsAreReadable) {
  EXPECT_EQ(format_duration(45.2), "45 s");
  EXPECT_EQ(format_duration(723.0), "12 min 03 s");
  EXPECT_EQ(format_duration(3 * 3600 + 5 * 60 + 10), "3 h 05 min");
  EXPECT_EQ(format_duration(-3.0), "0 s");
}

}  // namespace
}  // namespace rkpm::io

TEST(Progress, OpenEndedRunShowsItsDetailInsteadOfPercentAndEta) {
  std::ostringstream out;
  rkpm::io::Progress p(out, false);
  p.update(12, 3e-7, 0.0, 2.5e-9, 1.0, "residual 3.10e-03 (target 1e-04)");
  const std::string line = p.line();
  EXPECT_NE(line.find("step 12"), std::string::npos) << line;
  EXPECT_NE(line.find("residual 3.10e-03 (target 1e-04)"), std::string::npos) << line;
  EXPECT_EQ(line.find('%'), std::string::npos) << line;
  EXPECT_EQ(line.find("ETA"), std::string::npos) << line;
}
