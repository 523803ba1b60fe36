// Run under mpirun with 2 ranks (tests/par/CMakeLists.txt), or any N >= 2 by hand. Whole runs of the sag
// example (a clamped Mooney-Rivlin block under a body force) distributed over the
// ranks against a one-rank run of the same scene in the same process (Comm::self()):
// the relaxation lands on the same state, 200 dynamic steps follow the same path, a
// restart on the same rank count continues bit for bit, and what cannot run
// distributed, or blows up, ends every rank with one message and one exit code.
#include "rkpm/io/pvd_series.hpp"
#include "rkpm/par/comm.hpp"
#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/compare_command.hpp"
#include "rkpm/sim/run.hpp"
#include "rkpm/sim/shape_command.hpp"
#include "sim_fixtures.hpp"
#include "vtu_read_back.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

using namespace rkpm;
using namespace rkpm::sim;
using namespace rkpm::sim::testing;
namespace fs = std::filesystem;

namespace {

const par::Comm& world() { return par::Comm::world(); }

std::string sag_scene() { return read_text(fs::path(RKPM_SOURCE_DIR) / "examples/sag/sag.toml"); }

// `text` with its one occurrence of `old` replaced (throws if absent: a test must not
// silently run the unmodified scene).
std::string replaced(std::string text, const std::string& old, const std::string& by) {
  const auto at = text.find(old);
  if (at == std::string::npos) throw std::invalid_argument("'" + old + "' not in the scene text");
  return text.replace(at, old.size(), by);
}

// One directory for every rank: rank 0 names it.
fs::path shared_dir(const std::string& tag) {
  std::string name = world().root() ? fresh_dir(tag).string() : std::string();
  return fs::path(world().broadcast(name, 0));
}

struct Outcome {
  int code = -1;
  std::string log;
};

Outcome run(const std::string& text, const fs::path& out, const par::Comm& comm, std::int64_t max_steps = 0,
            const fs::path& restart = {}, bool allow_unstable = false) {
  const auto scene = scene::parse_scene(text, (fs::path(RKPM_SOURCE_DIR) / "examples/sag/sag.toml").string());
  RunOptions options;
  options.out_dir = out;
  options.quiet = true;
  options.comm = &comm;
  options.max_steps_override = max_steps;
  options.restart = restart;
  options.allow_unstable_dt = allow_unstable;
  std::ostringstream log;
  Outcome o;
  o.code = run_scene(scene, options, log);
  o.log = log.str();
  return o;
}

// Final positions by (body_id, particle_id), read through VTK as ParaView would (.vtu or
// .pvtu). A distributed frame flags its halo copies as vtkGhostType duplicates: every
// particle is unflagged in exactly one piece, and a flagged copy sits where its owner's does.
using ParticleKey = std::pair<std::int64_t, std::int64_t>;
std::map<ParticleKey, Vec3> final_positions(const fs::path& dir, double* largest_displacement) {
  const auto entries = io::read_pvd(dir / "frames.pvd");
  const auto frame = io::test::read_vtu_back(dir / entries.back().file);
  const auto& body = frame.point_fields.at("body_id").values;
  const auto& ids = frame.point_fields.at("particle_id").values;
  const auto& u = frame.point_fields.at("displacement").values;
  const bool pieces = fs::path(entries.back().file).extension() == ".pvtu";
  EXPECT_EQ(frame.ghost_type.size(), pieces ? frame.points.size() : 0u);
  std::map<ParticleKey, Vec3> p, copies;
  for (std::size_t i = 0; i < frame.points.size(); ++i) {
    const ParticleKey key{static_cast<std::int64_t>(body[i]), static_cast<std::int64_t>(ids[i])};
    if (!frame.ghost_type.empty() && frame.ghost_type[i] != 0) {
      EXPECT_EQ(frame.ghost_type[i], 1) << "DUPLICATEPOINT";
      copies[key] = frame.points[i];
      continue;
    }
    EXPECT_TRUE(p.emplace(key, frame.points[i]).second) << "particle " << key.second << " unflagged twice";
    if (largest_displacement)
      *largest_displacement = std::max(*largest_displacement, Vec3(u[3 * i], u[3 * i + 1], u[3 * i + 2]).norm());
  }
  if (pieces) {
    EXPECT_GT(copies.size(), 0u) << "the pieces share nodes";
  }
  for (const auto& [key, x] : copies) {
    const auto owner = p.find(key);
    if (owner == p.end())
      ADD_FAILURE() << "a halo copy of particle " << key.second << " whose owner wrote none";
    else
      EXPECT_EQ(owner->second, x);
  }
  return p;
}

// The largest distance between the two runs' final positions, over the largest displacement.
double compare_final(const fs::path& serial, const fs::path& distributed) {
  double scale = 0.0;
  const auto a = final_positions(serial, &scale);
  const auto b = final_positions(distributed, nullptr);
  EXPECT_EQ(a.size(), b.size()) << "every particle appears in the distributed frame";
  double worst = 0.0;
  for (const auto& [id, p] : a) {
    const auto it = b.find(id);
    if (it == b.end()) {
      ADD_FAILURE() << "particle " << id.second << " of body " << id.first << " missing from the distributed frame";
      continue;
    }
    worst = std::max(worst, (it->second - p).norm());
  }
  EXPECT_GT(scale, 0.0);
  return worst / scale;
}

std::string json_value(const std::string& text, const std::string& key) {
  const auto at = text.find("\"" + key + "\"");
  if (at == std::string::npos) return {};
  const auto start = text.find(':', at) + 1;
  return text.substr(start, text.find_first_of(",\n}", start) - start);
}

std::string summary_value(const fs::path& dir, const std::string& key) {
  return json_value(read_text(dir / "summary.json"), key);
}

// Runs `text` over every rank into dir/two, then (rank 0 only) as one process into
// dir/one. Returns the final-position difference (compare_final) on rank 0, NaN on the
// others, which have nothing left to check.
double run_both_ways(const std::string& text, const fs::path& dir, std::int64_t max_steps = 0) {
  const Outcome d = run(text, dir / "two", world(), max_steps);
  EXPECT_EQ(d.code, kSuccess) << d.log;
  if (!world().root()) return std::nan("");
  const Outcome s = run(text, dir / "one", par::Comm::self(), max_steps);
  EXPECT_EQ(s.code, kSuccess) << s.log;
  return compare_final(dir / "one", dir / "two");
}

}  // namespace

TEST(DistributedRun, SagRelaxationLandsOnTheOneRankState) {
  ASSERT_GE(world().size(), 2) << "run this test with mpirun -np N, N >= 2 (the suite uses 2)";
  const fs::path dir = shared_dir("sag_relax");
  const double error = run_both_ways(sag_scene(), dir);
  if (!world().root()) return;
  EXPECT_EQ(summary_value(dir / "one", "steps"), summary_value(dir / "two", "steps"));
  std::cout << "relaxed sag, " << world().size() << " ranks against 1: final positions differ by " << error
            << " of the largest displacement; steps " << summary_value(dir / "two", "steps") << "\n";
  EXPECT_EQ(error, 0.0);  // the same bits: docs/theory/distributed.md
  EXPECT_TRUE(fs::exists(dir / "two" / "frames_000000_1.vtu"));
  EXPECT_TRUE(fs::exists(dir / "two" / "history.csv"));
}

TEST(DistributedRun, TwoHundredDynamicStepsFollowTheOneRankPath) {
  const fs::path dir = shared_dir("sag_dynamic");
  const std::string text = replaced(sag_scene(), "mode = \"relax\"", "mode = \"dynamic\"\nt_end = 1e-3\ndamping = 2e4");
  const double error = run_both_ways(text, dir, 200);
  if (!world().root()) return;
  std::cout << "dynamic sag, 200 steps, " << world().size() << " ranks against 1: " << error << " of the largest displacement\n";
  EXPECT_EQ(error, 0.0);
}

// A clamped face of 49 x 49 particles: its constraint system is solved in two parts
// (sim/integration/constraint_solver.hpp), one on each rank, and the run
// still follows the one-rank path to the bit.
TEST(DistributedRun, AClampedFaceSolvedInPartsFollowsTheOneRankPath) {
  const fs::path dir = shared_dir("sag_large_face");
  std::string text = replaced(sag_scene(), "mode = \"relax\"", "mode = \"dynamic\"\nt_end = 1e-3\ndamping = 2e4");
  text = replaced(text, "cells = [10, 10, 4]", "cells = [48, 48, 2]");
  const double error = run_both_ways(text, dir, 30);
  if (!world().root()) return;
  std::cout << "dynamic sag with a 2,401-particle clamped face, 30 steps, " << world().size()
            << " ranks against 1: " << error << " of the largest displacement\n";
  EXPECT_EQ(error, 0.0);
}

// A material with per-point state of its own (the viscoelastic model's viscous strains)
// follows the one-rank path to the bit: the state is updated at each rank's own points.
TEST(DistributedRun, AViscoelasticBlockFollowsTheOneRankPath) {
  const fs::path dir = shared_dir("sag_viscoelastic");
  std::string text = replaced(sag_scene(), "mode = \"relax\"", "mode = \"dynamic\"\nt_end = 1e-3\ndamping = 2e4");
  text = replaced(text, "model = \"mooney_rivlin\"\nc1 = 2.126e3\nc2 = 1.7e2\nlambda = 1.7e5",
                  "model = \"viscoelastic\"\nmu = 4.6e3\nlambda = 1.7e5\nbeta = [1.0, 0.5]\ntau = [2e-5, 1e-4]");
  const double error = run_both_ways(text, dir, 200);
  if (!world().root()) return;
  std::cout << "viscoelastic sag, 200 steps, " << world().size() << " ranks against 1: " << error << "\n";
  EXPECT_EQ(error, 0.0);
  EXPECT_EQ(summary_value(dir / "one", "state_work"), summary_value(dir / "two", "state_work"));
  EXPECT_NE(summary_value(dir / "one", "state_work"), "0") << "the branches did dissipate";
}

// The red-blood-cell example on a coarse cloud: the active LCE shell (director evolution
// with anchoring, the Frank term), its enclosed fluid (volume constraint), the faces'
// wall contact (its reach widened so that pairs are in contact within the run) with the
// example's contact mass scaling, the shape report, and FIRE relaxation from a nested
// level at half the resolution; 300 steps on the level and 300 on the shell itself.
TEST(DistributedRun, RedBloodCellSceneOnACoarseCloudFollowsTheOneRankPath) {
  const fs::path dir = shared_dir("rbc_coarse");
  std::string text = read_text(fs::path(RKPM_SOURCE_DIR) / "examples/rbc/rbc.toml");
  text = replaced(text, "nested_levels = [0.375, 0.625]", "nested_levels = [0.5]");
  text = replaced(text, "max_steps = 200000", "max_steps = 300");
  text = replaced(replaced(text, "face_cells = 32", "face_cells = 12"), "layers = 5", "layers = 3");
  text = replaced(text, "distance = 0.2e-6", "distance = 1.5e-6\nexclusion = 2.0e-6");
  const double error = run_both_ways(text, dir, 300);
  if (!world().root()) return;
  std::cout << "coarse RBC scene, nested level and 300 FIRE steps, " << world().size() << " ranks against 1: " << error
            << " of the largest displacement; wall-contact pairs " << summary_value(dir / "two", "active_pairs") << "\n";
  EXPECT_EQ(error, 0.0);
  EXPECT_GT(std::stoi(summary_value(dir / "one", "active_pairs")), 0);
  EXPECT_EQ(summary_value(dir / "one", "active_pairs"), summary_value(dir / "two", "active_pairs"));
  // The example's contact_mass_scaling made the pressed particles heavier on every rank
  // alike (each holds every surface point and pair: the one-process inertia).
  EXPECT_GT(std::stoi(summary_value(dir / "one", "heavier_particles")), 0);
  EXPECT_EQ(summary_value(dir / "one", "heavier_particles"), summary_value(dir / "two", "heavier_particles"));
  EXPECT_EQ(summary_value(dir / "one", "largest_inertia_over_mass"),
            summary_value(dir / "two", "largest_inertia_over_mass"));
  // Summed exactly over the ranks' cells, gathered from the ranks' particles: the same bits.
  for (const std::string key : {"volume_ratio", "h_min_over_h_max"})
    EXPECT_EQ(std::stod(summary_value(dir / "two", key)), std::stod(summary_value(dir / "one", key))) << key;
  EXPECT_TRUE(fs::exists(dir / "two" / "shape_profile.csv"));
  // `rkpm shape` reads the distributed run's last frame (a .pvtu of the ranks' pieces)
  // in the one-rank numbering: the report the run made from memory.
  write_text(dir / "rbc.toml", text);
  std::ostringstream out, log;
  ASSERT_EQ(run_shape_command({dir / "rbc.toml", dir / "two", "", dir / "from_frame.csv"}, out, log), kSuccess)
      << log.str();
  EXPECT_NEAR(std::stod(json_value(out.str(), "h_min_over_h_max")),
              std::stod(summary_value(dir / "two", "h_min_over_h_max")), 1e-7);
}

// The adhesion example on a coarse cloud: an LCE sphere (director with normal anchoring)
// landing on a Mooney-Rivlin block, with the two bodies' Lennard-Jones contact, the
// contact report and surface tension on both bodies. The skin is cut to 1/40 of the
// default so that the pair list, and with it each rank's ghosts of the other body, is
// rebuilt many times within the 200 steps.
TEST(DistributedRun, AdhesionSceneOnACoarseCloudFollowsTheOneRankPath) {
  const fs::path dir = shared_dir("adhesion_coarse");
  std::string text = read_text(fs::path(RKPM_SOURCE_DIR) / "examples/adhesion/adhesion.toml");
  text = replaced(text, "cells = 22", "cells = 8");
  text = replaced(text, "cells = [40, 40, 4]", "cells = [16, 16, 3]");
  // The 2.34 um grid needs s0 = 2 um to hold the cell (holding.hpp); eps keeps |W(d0)|,
  // and the cell starts 200 nm beyond the equilibrium gap 0.6368 s0 as in the scene.
  text = replaced(text, "s0 = 0.75e-6", "s0 = 2e-6");
  text = replaced(text, "epsilon = 3.265e-15", "epsilon = 6.457e-17");
  text = replaced(text, "center = [0.0, 0.0, 10.1776e-6]", "center = [0.0, 0.0, 10.9736e-6]");
  text = replaced(text, "report_surface = \"zmax\"", "report_surface = \"zmax\"\nskin = 0.01e-6");
  text = replaced(text, "every = 0.25e-6", "every = 0.02e-6");
  const double error = run_both_ways(text, dir, 200);
  if (!world().root()) return;
  std::cout << "coarse adhesion scene, 200 dynamic steps, " << world().size() << " ranks against 1: " << error
            << " of the largest displacement; contact pairs " << summary_value(dir / "two", "active_pairs")
            << ", pair-list builds " << summary_value(dir / "two", "pair_list_builds") << "\n";
  EXPECT_EQ(error, 0.0);
  // `rkpm compare` finds the same difference, reading the frames its own way.
  std::ostringstream out, log;
  ASSERT_EQ(run_compare_command({dir / "one", dir / "two"}, out, log), kSuccess) << log.str();
  EXPECT_DOUBLE_EQ(std::stod(json_value(out.str(), "relative_difference")), error) << out.str();
  EXPECT_GT(std::stoi(summary_value(dir / "one", "active_pairs")), 0);
  EXPECT_GT(std::stoi(summary_value(dir / "one", "pair_list_builds")), 3);
  for (const std::string key : {"active_pairs", "listed_pairs", "pair_list_builds", "contact_particles"})
    EXPECT_EQ(summary_value(dir / "one", key), summary_value(dir / "two", key)) << key;
  for (const std::string key : {"min_gap", "contact_radius"})
    EXPECT_EQ(std::stod(summary_value(dir / "two", key)), std::stod(summary_value(dir / "one", key))) << key;
  // The history's contact columns, written once by rank 0 from every rank's particles.
  const std::string history = read_text(dir / "two" / "history.csv");
  const std::string serial_history = read_text(dir / "one" / "history.csv");
  EXPECT_NE(history.find("contact_radius"), std::string::npos);
  EXPECT_EQ(std::count(history.begin(), history.end(), '\n'),
            std::count(serial_history.begin(), serial_history.end(), '\n'));
}

TEST(DistributedRun, RestartOnTheSameRankCountContinuesBitForBit) {
  const fs::path dir = shared_dir("sag_restart");
  const std::string text = replaced(sag_scene(), "mode = \"relax\"", "mode = \"dynamic\"\nt_end = 1e-3\ndamping = 2e4");
  const std::string checkpointed = replaced(text, "every = 1e-5", "every = 1e-5\ncheckpoint_every = 50");
  EXPECT_EQ(run(checkpointed, dir / "whole", world(), 150).code, kSuccess);
  EXPECT_EQ(run(checkpointed, dir / "parts", world(), 100).code, kSuccess);
  EXPECT_TRUE(fs::exists(dir / "parts" / ("checkpoint.bin." + std::to_string(world().rank()))));
  const Outcome resumed = run(checkpointed, dir / "parts", world(), 150, dir / "parts" / "checkpoint.bin");
  EXPECT_EQ(resumed.code, kSuccess) << resumed.log;
  if (world().root()) {
    EXPECT_EQ(compare_final(dir / "whole", dir / "parts"), 0.0);
    // The checkpoint of a 2-rank run is refused on one rank, naming the rank count.
    const Outcome single = run(checkpointed, dir / "single", par::Comm::self(), 150, dir / "parts" / "checkpoint.bin.0");
    EXPECT_EQ(single.code, kBadInput);
    EXPECT_NE(single.log.find("on " + std::to_string(world().size()) + " rank(s)"), std::string::npos) << single.log;
  }
}

// A scene that cannot be set up fails alike on every rank: rank 0 alone reports it.
TEST(DistributedRun, ASetUpErrorIsReportedOnceWithTheLine) {
  const fs::path dir = shared_dir("adhesion_refused");
  std::string text = read_text(fs::path(RKPM_SOURCE_DIR) / "examples/adhesion/adhesion.toml");
  text = replaced(text, "kappa = 1e-11", "kappa = 1e-11\nzeta = -1e3\nzeta_layer = \"inner\"");
  const Outcome d = run(text, dir / "two", world());
  EXPECT_EQ(d.code, kBadInput);
  if (world().root()) {
    EXPECT_NE(d.log.find("zeta_layer = \"inner\": expected \"all\""), std::string::npos) << d.log;
    EXPECT_NE(d.log.find("sag.toml:"), std::string::npos) << d.log;  // run() names every scene sag.toml
  } else {
    EXPECT_EQ(d.log, "");  // rank 0 speaks for the run
  }
  EXPECT_FALSE(fs::exists(dir / "two" / "frames.pvd"));
}

// Mass scaling (a median over every particle of every rank) and the measured stable
// step (a power iteration over the whole world): the sag relaxation with both lands on
// the one-process state in the same number of steps.
TEST(DistributedRun, MassScalingAndTheMeasuredStableStepFollowTheOneRankPath) {
  const fs::path dir = shared_dir("sag_scaled");
  const std::string text =
      replaced(sag_scene(), "mode = \"relax\"", "mode = \"relax\"\nmass_scaling = true\nstable_step = \"measured\"");
  const double error = run_both_ways(text, dir);
  if (!world().root()) return;
  std::cout << "sag relaxation with mass scaling and the measured stable step, " << world().size()
            << " ranks against 1: " << error << " of the largest displacement; steps " << summary_value(dir / "two", "steps")
            << "\n";
  EXPECT_EQ(error, 0.0);
  EXPECT_EQ(summary_value(dir / "one", "steps"), summary_value(dir / "two", "steps"));
  EXPECT_NE(summary_value(dir / "two", "converged").find("true"), std::string::npos);
  EXPECT_EQ(std::stod(summary_value(dir / "two", "stable_dt")), std::stod(summary_value(dir / "one", "stable_dt")));
}

TEST(DistributedRun, ABlowUpStopsEveryRankWithTheSameDiagnosis) {
  const fs::path dir = shared_dir("sag_unstable");
  const std::string text =
      replaced(sag_scene(), "mode = \"relax\"", "mode = \"dynamic\"\nt_end = 1e-3\ndt = 1e-6");
  const Outcome d = run(text, dir / "two", world(), 0, {}, true);
  EXPECT_EQ(d.code, kUnstable);
  if (world().root()) {
    EXPECT_NE(d.log.find("unstable at step"), std::string::npos) << d.log;
    EXPECT_NE(summary_value(dir / "two", "diagnosis"), "");
    const auto entries = io::read_pvd(dir / "two" / "frames.pvd");
    EXPECT_FALSE(entries.empty());  // the last good frame is kept
  }
}

int main(int argc, char** argv) {
  rkpm::par::Session mpi(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
