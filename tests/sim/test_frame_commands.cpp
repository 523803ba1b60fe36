// The commands that read a finished run's frames. `rkpm shape`: the shape report
// measured from a frame of a run equals the report of the same positions measured in
// memory. `rkpm compare`: two runs of a scene compared particle by particle. Bad input
// names the file and the problem.
#include "sim_fixtures.hpp"

#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/run.hpp"
#include "rkpm/sim/compare_command.hpp"
#include "rkpm/io/frame_points.hpp"
#include "rkpm/io/pvd_series.hpp"
#include "rkpm/sim/shape_command.hpp"
#include "rkpm/sim/shape_report.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace rkpm::sim {
namespace {

namespace fs = std::filesystem;
using testing::with;
using testing::write_text;

// A coarse thick shell squeezed along z, run for one step: its frames hold a shape
// that differs from the reference cloud.
const std::string kShell = R"([scene]
name = "shape"
[integrator]
t_end = 1.0
[output]
every = 1e-12
shape_report = "cell"
[[body]]
name = "cell"
density = 1000.0
[body.cloud]
generator = "shell"
semi_axes = [5e-6, 5e-6, 1.5e-6]
thickness = 0.5e-6
face_cells = {cells}
layers = 3
[body.material]
model = "mooney_rivlin"
c1 = 1e3
c2 = 0
lambda = 1e4
[body.initial]
stretch = [1.0, 1.0, 0.8]
)";

struct RunDir {
  fs::path dir, scene;
};

RunDir run_one_step(const std::string& tag, int cells) {
  RunDir r{testing::fresh_dir(tag), {}};
  r.scene = r.dir / "shell.toml";
  write_text(r.scene, with(kShell, "cells", std::to_string(cells)));
  RunOptions options;
  options.out_dir = r.dir / "out";
  options.max_steps_override = 1;
  options.quiet = true;
  std::ostringstream log;
  EXPECT_EQ(run_scene(scene::load_scene(r.scene.string()), options, log), kSuccess) << log.str();
  return r;
}

std::vector<std::vector<double>> read_csv(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream fields(line);
    // Empty fields (the inner surface's columns where it has no sheet) read as NaN and
    // are compared as absent; a row ending in empty fields is shorter (getline drops
    // the last empty one), the same in both files.
    for (std::string f; std::getline(fields, f, ',');) row.push_back(f.empty() ? std::nan("") : std::stod(f));
    rows.push_back(row);
  }
  return rows;
}

TEST(ShapeCommand, FrameReportEqualsTheRunsOwnReport) {
  const RunDir r = run_one_step("shape_command", 6);
  // The run wrote its final report (shape_profile.csv) from memory; the command
  // measures the last frame, written from the same state.
  std::ostringstream out, log;
  const fs::path csv = r.dir / "from_frame.csv";
  ASSERT_EQ(run_shape_command({r.scene, r.dir / "out", "", csv}, out, log), kSuccess) << log.str();
  const auto from_run = read_csv(r.dir / "out" / "shape_profile.csv");
  const auto from_frame = read_csv(csv);
  ASSERT_EQ(from_run.size(), from_frame.size());
  ASSERT_GT(from_run.size(), 8u);
  for (std::size_t k = 0; k < from_run.size(); ++k) {
    ASSERT_EQ(from_frame[k].size(), from_run[k].size()) << "row " << k;
    for (std::size_t c = 0; c < from_run[k].size(); ++c) {
      ASSERT_EQ(std::isnan(from_frame[k][c]), std::isnan(from_run[k][c])) << "row " << k << " column " << c;
      if (!std::isnan(from_run[k][c])) {
        EXPECT_NEAR(from_frame[k][c], from_run[k][c], 1e-7 * std::abs(from_run[k][c]) + 1e-16);
      }
    }
  }
  // The shell's inner surface gives the fluid gap on the axis (inner_top, inner_bottom).
  ASSERT_EQ(from_run.front().size(), 7u);
  EXPECT_GT(from_run.front()[5] - from_run.front()[6], 0.0);
  EXPECT_NE(out.str().find("\"walls_crossed\": false"), std::string::npos) << out.str();
  // The squeezed start (stretch 0.8 along z) is thinner than the reference cloud.
  EXPECT_NE(out.str().find("\"h_max\": 2.4"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("\"biconcave\": false"), std::string::npos) << out.str();
}

TEST(ShapeCommand, FrameOfAnotherCloudIsRejectedWithBothCounts) {
  const RunDir coarse = run_one_step("shape_command_coarse", 6);
  const RunDir fine = run_one_step("shape_command_fine", 8);
  std::ostringstream out, log;
  EXPECT_EQ(run_shape_command({fine.scene, coarse.dir / "out", "", coarse.dir / "x.csv"}, out, log), kBadInput);
  EXPECT_NE(log.str().find("points, but the bodies of"), std::string::npos) << log.str();
  EXPECT_NE(log.str().find("frames_"), std::string::npos) << log.str();
}

TEST(ShapeCommand, MissingFrameAndUnknownBodyAreNamed) {
  const RunDir r = run_one_step("shape_command_bad", 6);
  std::ostringstream out, log;
  EXPECT_EQ(run_shape_command({r.scene, r.dir / "nothing.vtu", "", ""}, out, log), kBadInput);
  EXPECT_NE(log.str().find("nothing.vtu: no such file"), std::string::npos) << log.str();
  log.str("");
  EXPECT_EQ(run_shape_command({r.scene, r.dir / "out", "membrane", ""}, out, log), kBadInput);
  EXPECT_NE(log.str().find("no body named 'membrane'"), std::string::npos) << log.str();
}

// The value of `"key": value` in the command's JSON line.
double json_number(const std::string& text, const std::string& key) {
  const auto at = text.find("\"" + key + "\": ");
  if (at == std::string::npos) throw std::invalid_argument(key + " not in " + text);
  return std::stod(text.substr(at + key.size() + 4));
}

TEST(CompareCommand, ARerunEndsWhereTheRunEndedAndTheFirstStepMovesFromTheStart) {
  const RunDir a = run_one_step("compare_a", 6);
  const RunDir b = run_one_step("compare_b", 6);
  std::ostringstream out, log;
  ASSERT_EQ(run_compare_command({a.dir / "out", b.dir / "out"}, out, log), kSuccess) << log.str();
  EXPECT_EQ(json_number(out.str(), "largest_difference"), 0.0) << out.str();  // deterministic
  EXPECT_GT(json_number(out.str(), "particles"), 100.0);

  // The initial frame against the last: the particles moved by the step, at most by
  // their largest displacement plus the initial stretch's.
  const auto entries = io::read_pvd(a.dir / "out" / "frames.pvd");
  ASSERT_GE(entries.size(), 2u);
  const fs::path first = a.dir / "out" / entries.front().file, last = a.dir / "out" / entries.back().file;
  out.str("");
  ASSERT_EQ(run_compare_command({last, first}, out, log), kSuccess) << log.str();
  const io::FramePoints p = io::read_frame_points(last), q = io::read_frame_points(first);
  double moved = 0.0, largest = 0.0;
  for (std::size_t k = 0; k < p.position.size(); ++k) {
    moved = std::max(moved, (p.position[k] - q.position[k]).norm());
    largest = std::max(largest, p.displacement[k].norm());
  }
  EXPECT_GT(moved, 0.0);
  EXPECT_EQ(json_number(out.str(), "largest_difference"), moved);
  EXPECT_EQ(json_number(out.str(), "largest_displacement"), largest);
  EXPECT_NEAR(json_number(out.str(), "relative_difference"), moved / largest, 1e-15);
}

TEST(CompareCommand, RunsOfDifferentCloudsAndMissingFramesAreRefused) {
  const RunDir coarse = run_one_step("compare_coarse", 6);
  const RunDir fine = run_one_step("compare_fine", 8);
  std::ostringstream out, log;
  EXPECT_EQ(run_compare_command({coarse.dir / "out", fine.dir / "out"}, out, log), kBadInput);
  EXPECT_NE(log.str().find("different bodies or particle counts"), std::string::npos) << log.str();
  log.str("");
  EXPECT_EQ(run_compare_command({coarse.dir / "out", coarse.dir / "nothing.pvtu"}, out, log), kBadInput);
  EXPECT_NE(log.str().find("nothing.pvtu: no such file"), std::string::npos) << log.str();
  EXPECT_EQ(out.str(), "");
}

}  // namespace
}  // namespace rkpm::sim
