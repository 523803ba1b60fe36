// The run loop: bit-for-bit restart from a checkpoint, the diagnosis of a blow-up
// with the last good frame kept, the clamping of a too-large user step, and the
// relaxation's progress line.
#include "sim_fixtures.hpp"
#include "vtu_read_back.hpp"

#include "rkpm/io/pvd_series.hpp"
#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/run.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <regex>
#include <sstream>

namespace rkpm::sim {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::with;
using testing::write_text;

// A Mooney-Rivlin block released from a stretch, and an active LCE ball whose
// director evolves (mobility, Frank term, surface anchoring): every kind of state a
// checkpoint must carry.
const std::string kTwoBodies = R"([scene]
name = "restart"
[integrator]
t_end = 1.0
dt_safety = 0.4
[output]
every = {every}
checkpoint_every = 10
[[body]]
name = "block"
[body.cloud]
generator = "block"
size = [1e-5, 1e-5, 1e-5]
cells = [3, 3, 3]
jitter = 0.1
[body.material]
model = "mooney_rivlin"
c1 = 400
c2 = 100
lambda = 4000
[body.initial]
stretch = [1.1, 0.95, 1.0]
random_velocity = 1e-3
[[body.boundary]]
surface = "zmin"
[[body]]
name = "gel"
[body.cloud]
generator = "sphere"
center = [3e-5, 0, 0]
radius = 5e-6
cells = 4
[body.material]
model = "lce"
mu = 1000
bulk = 1e5
kappa = 1e-12
mobility = 1e-2
zeta = 300
[body.director]
initial = "radial"
[body.initial]
random_velocity = 1e-3
[[term]]
type = "body_force"
body = "gel"
acceleration = [0, 0, -1e3]
)";

struct RunResult {
  int code = -1;
  std::string log;
};

RunResult run_file(const fs::path& scene_file, const fs::path& out, std::int64_t max_steps, const fs::path& restart = {},
        bool allow_unstable_dt = false, bool quiet = true) {
  const scene::Scene scene = scene::load_scene(scene_file.string());
  RunOptions options;
  options.out_dir = out;
  options.restart = restart;
  options.max_steps_override = max_steps;
  options.allow_unstable_dt = allow_unstable_dt;
  options.quiet = quiet;
  std::ostringstream log;
  RunResult r;
  r.code = run_scene(scene, options, log);
  r.log = log.str();
  return r;
}

// The number after `"key": ` in a summary.json.
double summary_number(const fs::path& summary, const std::string& key) {
  const std::string text = read_text(summary);
  const std::smatch m = [&] {
    std::smatch match;
    std::regex_search(text, match, std::regex("\"" + key + "\": (-?[0-9.eE+-]+)"));
    return match;
  }();
  if (m.empty()) throw std::runtime_error("no number '" + key + "' in " + summary.string());
  return std::stod(m[1].str());
}

io::test::ReadBack last_frame(const fs::path& out) {
  const auto entries = io::read_pvd(out / "frames.pvd");
  if (entries.empty()) throw std::runtime_error("empty series in " + out.string());
  return io::test::read_vtu_back(out / entries.back().file);
}

TEST(Restart, ResumedRunEndsBitForBitLikeTheUninterruptedOne) {
  testing::ScopedThreads two(2);  // the contract: same scene, build and thread count
  const fs::path dir = testing::fresh_dir("restart");
  const fs::path scene_file = dir / "restart.toml";
  write_text(scene_file, with(kTwoBodies, "every", "1e-7"));

  const RunResult whole = run_file(scene_file, dir / "whole", 40);
  ASSERT_EQ(whole.code, kSuccess) << whole.log;

  const RunResult first = run_file(scene_file, dir / "split", 20);
  ASSERT_EQ(first.code, kSuccess) << first.log;
  fs::copy_file(dir / "split" / "checkpoint.bin", dir / "step20.bin");
  const RunResult second = run_file(scene_file, dir / "split", 40, dir / "step20.bin");
  ASSERT_EQ(second.code, kSuccess) << second.log;

  // The checkpoints written at step 40 hold the whole dynamic state (d, v, the forces, the
  // directors, constraint targets, the integrator's ledger and FIRE state).
  const std::string a = read_text(dir / "whole" / "checkpoint.bin"), b = read_text(dir / "split" / "checkpoint.bin");
  std::printf("checkpoint at step 40: %zu bytes uninterrupted, %zu bytes resumed, identical: %s\n", a.size(), b.size(),
              a == b ? "yes" : "no");
  EXPECT_EQ(a, b);
  EXPECT_NE(a, read_text(dir / "step20.bin"));  // the state did change after step 20

  for (const char* key : {"steps", "simulated_time", "kinetic", "strain", "external_work", "active_work", "min_J"})
    EXPECT_EQ(summary_number(dir / "whole" / "summary.json", key), summary_number(dir / "split" / "summary.json", key))
        << key;
  EXPECT_EQ(summary_number(dir / "whole" / "summary.json", "steps"), 40);

  const auto fa = last_frame(dir / "whole"), fb = last_frame(dir / "split");
  ASSERT_EQ(fa.points.size(), fb.points.size());
  for (std::size_t i = 0; i < fa.points.size(); ++i) ASSERT_EQ(fa.points[i], fb.points[i]) << "point " << i;
  ASSERT_TRUE(fa.point_fields.count("director"));
  for (const auto& [name, field] : fa.point_fields) EXPECT_EQ(field.values, fb.point_fields.at(name).values) << name;
  fs::remove_all(dir);
}

// The stable step of the scene's initial state, from a world built the same way.
double initial_stable_dt(const std::string& toml) {
  auto sw = testing::build_from_text(toml);
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  return integrator.stable_dt();
}

const std::string kBlock = R"([scene]
name = "block"
[integrator]
t_end = {t_end}
dt = {dt}
[output]
every = {every}
[[body]]
name = "cube"
[body.cloud]
generator = "block"
size = [1e-5, 1e-5, 1e-5]
cells = [3, 3, 3]
[body.material]
model = "mooney_rivlin"
c1 = 400
lambda = 4000
[body.initial]
random_velocity = 1e-2
[[body.boundary]]
surface = "zmin"
)";

std::string block_scene(double t_end, double dt, double every) {
  auto fmt = [](double x) {
    char s[32];
    std::snprintf(s, sizeof s, "%.17g", x);
    return std::string(s);
  };
  return with(with(with(kBlock, "t_end", fmt(t_end)), "dt", fmt(dt)), "every", fmt(every));
}

TEST(BlowUp, ForcedUnstableStepStopsWithDiagnosisAndKeepsTheLastGoodFrame) {
  testing::ScopedThreads one(1);
  const double stable = initial_stable_dt(block_scene(1.0, 0.0, 1.0));
  const double dt = 4.0 * stable;
  const fs::path dir = testing::fresh_dir("blowup");
  write_text(dir / "blowup.toml", block_scene(1e4 * dt, dt, dt));
  const RunResult r = run_file(dir / "blowup.toml", dir / "out", 0, {}, true);
  std::printf("dt = 4 x stable (%.4g s): exit code %d; log:\n%s", stable, r.code, r.log.c_str());
  ASSERT_EQ(r.code, kUnstable);

  // The diagnosis names the step, time, body, particle and the quantity that failed.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.log, m, std::regex(R"(unstable at step (\d+) \(t = ([0-9.eE+-]+) s)"))) << r.log;
  const long step = std::stol(m[1].str());
  EXPECT_NE(r.log.find("body 'cube'"), std::string::npos);
  EXPECT_TRUE(std::regex_search(r.log, std::regex(R"(particle \d+ )")));
  EXPECT_TRUE(std::regex_search(r.log, std::regex("not finite|inverted|left the domain")));
  EXPECT_NE(r.log.find("the last good frame is kept"), std::string::npos);
  const fs::path summary = dir / "out" / "summary.json";
  EXPECT_EQ(summary_number(summary, "steps"), step);
  EXPECT_NE(read_text(summary).find("\"status\": \"unstable\""), std::string::npos);

  // Every listed frame reads back through VTK with finite values, and the series ends
  // at the last step before the failure (a frame is written after every step).
  const auto entries = io::read_pvd(dir / "out" / "frames.pvd");
  ASSERT_GE(entries.size(), 2u);
  for (const auto& e : entries) {
    const auto frame = io::test::read_vtu_back(dir / "out" / e.file);
    for (const auto& p : frame.points) ASSERT_TRUE(p.allFinite()) << e.file;
    for (const auto& [name, field] : frame.point_fields)
      for (double v : field.values) ASSERT_TRUE(std::isfinite(v)) << e.file << " " << name;
  }
  const double failed_at = summary_number(summary, "simulated_time");
  std::printf("blow-up at step %ld, t = %.6g s; %zu frames listed, the last at t = %.6g s\n", step, failed_at,
              entries.size(), entries.back().time);
  EXPECT_LT(entries.back().time, failed_at);
  EXPECT_GT(entries.back().time, failed_at - 1.5 * dt);
  fs::remove_all(dir);
}

TEST(StepClamping, UserStepAboveTheStableStepIsClampedWithAWarning) {
  testing::ScopedThreads one(1);
  const double stable = initial_stable_dt(block_scene(1.0, 0.0, 1.0));
  const double requested = 10.0 * stable;
  const fs::path dir = testing::fresh_dir("clamp");
  write_text(dir / "clamp.toml", block_scene(20.0 * requested, requested, 20.0 * requested));
  const RunResult r = run_file(dir / "clamp.toml", dir / "out", 0);
  std::printf("requested dt %.4g s = 10 x stable: exit code %d; log:\n%s", requested, r.code, r.log.c_str());
  ASSERT_EQ(r.code, kSuccess);
  EXPECT_TRUE(std::regex_search(r.log, std::regex(R"(warning: \[integrator\] dt = \S+ s exceeds the stable step)")));
  const double used = summary_number(dir / "out" / "summary.json", "dt");
  const double stable_end = summary_number(dir / "out" / "summary.json", "stable_dt");
  EXPECT_LE(used, 0.5 * stable_end * (1.0 + 1e-12));  // the default dt_safety
  EXPECT_LT(used, 0.1 * requested);
  fs::remove_all(dir);
}

// A relaxation keeps going while either criterion fails, and its progress line shows
// both, so a run whose residual is below its target says that it waits for the kinetic
// energy. The last line carries the values summary.json reports at the end.
// A block sagging under its own weight, relaxed to tight criteria; `extra` goes into
// [integrator], `cells` is the block's cell count per direction.
std::string relaxing_block_scene(const std::string& name, const std::string& extra, const std::string& cells) {
  return fmt::format(R"([scene]
name = "{}"
[integrator]
mode = "relax"
relax_force_tol = 1e-5
relax_velocity_tol = 1e-9
{}
[[body]]
name = "block"
density = 1000
[body.cloud]
generator = "block"
size = [1e-5, 1e-5, 4e-6]
cells = {}
[body.material]
model = "neo_hookean"
mu = 1e3
lambda = 4e3
[[body.boundary]]
surface = "zmin"
type = "fixed"
[[term]]
type = "body_force"
body = "block"
acceleration = [0, 0, -1e4]
)",
                     name, extra, cells);
}

// The last match of `pattern` in `log` (empty when there is none) and where it starts.
struct LastMatch {
  std::smatch match;
  std::size_t position = 0;
};
LastMatch last_match(const std::string& log, const std::regex& pattern) {
  LastMatch last;
  for (auto it = std::sregex_iterator(log.begin(), log.end(), pattern); it != std::sregex_iterator(); ++it) {
    last.match = *it;
    last.position = static_cast<std::size_t>(it->position());
  }
  return last;
}

TEST(RelaxProgress, TheLineShowsBothCriteriaWithTheRunsValues) {
  testing::ScopedThreads one(1);
  const fs::path dir = testing::fresh_dir("relax_progress");
  write_text(dir / "sag.toml", relaxing_block_scene("relax_progress", "", "[4, 4, 2]"));
  const RunResult r = run_file(dir / "sag.toml", dir / "out", 40, {}, false, false);
  ASSERT_EQ(r.code, kSuccess) << r.log;
  const std::regex line(R"(residual ([0-9.e+-]+) \(target 1e-05\), kinetic ([0-9.e+-]+) \(target 1e-09\))");
  const std::smatch m = last_match(r.log, line).match;
  const std::string last = m.str();
  ASSERT_FALSE(last.empty()) << r.log;
  const double residual = summary_number(dir / "out" / "summary.json", "residual");
  const double kinetic = summary_number(dir / "out" / "summary.json", "kinetic_measure");
  std::printf("last progress line: %s; summary: residual %.3e, kinetic %.3e\n", last.c_str(), residual, kinetic);
  EXPECT_NEAR(std::stod(m[1].str()), residual, 0.006 * residual);  // printed to 3 digits
  EXPECT_NEAR(std::stod(m[2].str()), kinetic, 0.06 * kinetic);     // printed to 2 digits
  fs::remove_all(dir);
}

// A nested level shows the same progress line, labelled with the level, and ends it
// before the level's own line: a long coarse relaxation is not silent.
TEST(RelaxProgress, ANestedLevelShowsItsOwnLineBeforeItsResult) {
  testing::ScopedThreads one(1);
  const fs::path dir = testing::fresh_dir("relax_progress_levels");
  write_text(dir / "sag.toml", relaxing_block_scene("relax_progress_levels", "nested_levels = [0.5]", "[8, 8, 4]"));
  const RunResult r = run_file(dir / "sag.toml", dir / "out", 40, {}, false, false);
  ASSERT_EQ(r.code, kSuccess) << r.log;
  const std::regex progress(R"(level 1/1: residual ([0-9.e+-]+) \(target 1e-05\), kinetic ([0-9.e+-]+))");
  const LastMatch found = last_match(r.log, progress);
  const std::smatch& last = found.match;
  const std::size_t last_at = found.position;
  ASSERT_FALSE(last.empty()) << r.log;
  std::smatch result;
  const std::regex level_line(R"(nested level 1/1: factor 0.5, [0-9]+ particles, converged after [0-9]+ steps \(residual ([0-9.e+-]+)\))");
  ASSERT_TRUE(std::regex_search(r.log, result, level_line)) << r.log;
  EXPECT_LT(last_at, static_cast<std::size_t>(result.position())) << r.log;
  // The level's last progress line shows the residual it converged with.
  const double shown = std::stod(last[1].str()), reported = std::stod(result[1].str());
  EXPECT_NEAR(shown, reported, 0.006 * reported) << r.log;
  // Then the transfer of the level's state to the scene's own cloud, its sweeps and the
  // mismatch it left, in the log and in summary.json alike.
  std::smatch carried;
  const std::regex transfer_line(
      R"(state carried to ([0-9]+) particles in ([0-9]+) sweeps, mismatch ([0-9.e+-]+) of the largest displacement)");
  ASSERT_TRUE(std::regex_search(r.log, carried, transfer_line)) << r.log;
  EXPECT_GT(static_cast<std::size_t>(carried.position()), static_cast<std::size_t>(result.position())) << r.log;
  const fs::path summary = dir / "out" / "summary.json";
  EXPECT_EQ(std::stoi(carried[1].str()), static_cast<int>(summary_number(summary, "total_particles")));
  EXPECT_EQ(std::stoi(carried[2].str()), static_cast<int>(summary_number(summary, "transfer_sweeps")));
  const double mismatch = summary_number(summary, "transfer_mismatch");
  EXPECT_NEAR(std::stod(carried[3].str()), mismatch, 0.06 * mismatch) << "printed to 2 digits";
  EXPECT_LT(mismatch, 0.05) << "the carried field must arrive within a few per cent of the largest displacement";
  fs::remove_all(dir);
}

// relax_finish = "newton_krylov": after FIRE's stop the run reports the finish on its
// log (a line per Newton step unless quiet, then the outcome) and in summary.json, and
// ends at the finish's residual.
TEST(NewtonKrylovFinish, TheRunEndsAtItsTargetAndReportsIt) {
  testing::ScopedThreads one(1);
  const fs::path dir = testing::fresh_dir("newton_finish");
  write_text(dir / "sag.toml", relaxing_block_scene("newton_finish",
                                                    "relax_finish = \"newton_krylov\"\nfinish_force_tol = 1e-11",
                                                    "[4, 4, 2]"));
  const RunResult r = run_file(dir / "sag.toml", dir / "out", 0, {}, false, /*quiet=*/false);
  ASSERT_EQ(r.code, kSuccess) << r.log;
  EXPECT_NE(r.log.find("newton-krylov: converged after"), std::string::npos) << r.log;
  // The progress lines count the Newton steps 1, 2, ... up to the summary's, and the
  // last one shows the residual the finish ended at.
  const std::regex step_line(R"(newton-krylov step ([0-9]+): residual ([0-9.eE+-]+) \(target 1e-11\))");
  int lines = 0;
  double last_shown = -1.0;
  for (auto it = std::sregex_iterator(r.log.begin(), r.log.end(), step_line); it != std::sregex_iterator(); ++it) {
    EXPECT_EQ(std::stoi((*it)[1].str()), ++lines) << r.log;
    last_shown = std::stod((*it)[2].str());
  }
  ASSERT_GT(lines, 0) << r.log;
  EXPECT_EQ(lines, static_cast<int>(summary_number(dir / "out" / "summary.json", "newton_steps"))) << r.log;
  const double final_residual = summary_number(dir / "out" / "summary.json", "residual");
  EXPECT_NEAR(last_shown, final_residual, 0.006 * final_residual) << r.log;
  const std::string summary = read_text(dir / "out" / "summary.json");
  EXPECT_NE(summary.find("\"newton_krylov\""), std::string::npos);
  EXPECT_NE(summary.find("\"stop\": \"converged\""), std::string::npos) << summary;
  EXPECT_LT(summary_number(dir / "out" / "summary.json", "residual"), 1e-11);
  EXPECT_GT(summary_number(dir / "out" / "summary.json", "krylov_iterations"), 0);
  fs::remove_all(dir);
}

// The last frame shows the finished state even when FIRE's last step falls on an output
// time (a frame after every step here): it matches the last frame of the same run that
// writes only its first and last frames.
TEST(NewtonKrylovFinish, TheLastFrameIsTheFinishedState) {
  testing::ScopedThreads one(1);
  const fs::path dir = testing::fresh_dir("newton_finish_frames");
  const std::string scene =
      relaxing_block_scene("newton_finish_frames", "relax_finish = \"newton_krylov\"\nfinish_force_tol = 1e-11",
                           "[4, 4, 2]");
  write_text(dir / "every_step.toml", scene + "[output]\nevery = 1e-15\n");
  write_text(dir / "ends_only.toml", scene);
  ASSERT_EQ(run_file(dir / "every_step.toml", dir / "every_step", 0).code, kSuccess);
  ASSERT_EQ(run_file(dir / "ends_only.toml", dir / "ends_only", 0).code, kSuccess);
  const auto every_step = last_frame(dir / "every_step"), ends_only = last_frame(dir / "ends_only");
  EXPECT_EQ(io::read_pvd(dir / "every_step" / "frames.pvd").size(),
            static_cast<std::size_t>(summary_number(dir / "every_step" / "summary.json", "steps")) + 1);
  ASSERT_EQ(every_step.points.size(), ends_only.points.size());
  for (std::size_t i = 0; i < every_step.points.size(); ++i)
    ASSERT_EQ(every_step.points[i], ends_only.points[i]) << "point " << i;
  fs::remove_all(dir);
}

// A finish that runs out of Newton steps ends the run as not converged (exit code 4),
// with the state it reached in the series.
TEST(NewtonKrylovFinish, RunningOutOfNewtonStepsIsNotConvergence) {
  testing::ScopedThreads one(1);
  const fs::path dir = testing::fresh_dir("newton_finish_short");
  write_text(dir / "sag.toml",
             relaxing_block_scene("newton_finish_short",
                                  "relax_finish = \"newton_krylov\"\nfinish_force_tol = 1e-14\nfinish_max_newton_steps = 1",
                                  "[4, 4, 2]"));
  const RunResult r = run_file(dir / "sag.toml", dir / "out", 0);
  EXPECT_EQ(r.code, kIncomplete) << r.log;
  EXPECT_NE(r.log.find("1 Newton steps without reaching the target"), std::string::npos) << r.log;
  EXPECT_NE(read_text(dir / "out" / "summary.json").find("\"status\": \"not converged\""), std::string::npos);
  EXPECT_GE(io::read_pvd(dir / "out" / "frames.pvd").size(), 2u);
  fs::remove_all(dir);
}

// The finish carries a director with the coordinates; one that relaxes by itself (L > 0)
// is an unknown of its own, and the run refuses it before anything is written, naming
// the key and the body.
TEST(NewtonKrylovFinish, ADirectorThatRelaxesIsRefused) {
  const fs::path dir = testing::fresh_dir("newton_finish_lce");
  write_text(dir / "gel.toml", R"([scene]
name = "gel"
[integrator]
mode = "relax"
relax_finish = "newton_krylov"
[[body]]
name = "gel"
[body.cloud]
generator = "sphere"
radius = 5e-6
cells = 3
[body.material]
model = "lce"
mu = 1000
bulk = 1e5
mobility = 1e-2
)");
  const RunResult r = run_file(dir / "gel.toml", dir / "out", 0);
  EXPECT_EQ(r.code, kBadInput);
  EXPECT_NE(r.log.find("gel.toml:5: [integrator] relax_finish = \"newton_krylov\": body 'gel'"), std::string::npos)
      << r.log;
  EXPECT_FALSE(fs::exists(dir / "out"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rkpm::sim
