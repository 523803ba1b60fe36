// The pre-flight estimate (sim/preflight.hpp): exact particle counts for the
// generators, operator entries close to those of the built operators, refusals that
// name the key, the estimate and the limit, and no allocation before refusing.
#include "sim_fixtures.hpp"

#include "rkpm/particles/generators.hpp"
#include "rkpm/sim/preflight.hpp"
#include "rkpm/sim/run.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>

namespace rkpm::sim {
namespace {

std::string scene_with_cloud(const std::string& cloud, const std::string& extra = "") {
  return R"([scene]
name = "preflight"
[integrator]
mode = "relax"
[[body]]
name = "body"
density = 1000
[body.cloud]
)" + cloud + R"(
[body.material]
model = "mooney_rivlin"
c1 = 400
lambda = 2000
)" + extra;
}

const std::string kBlock = "generator = \"block\"\nsize = [2, 1, 0.5]\ncells = [12, 6, 3]";
const std::string kSphere = "generator = \"sphere\"\nradius = 1\ncells = 10";
const std::string kShell = "generator = \"shell\"\nsemi_axes = [5e-6, 5e-6, 1.5e-6]\nthickness = 0.5e-6\nface_cells = 12\nlayers = 5";

struct Built {
  double particles, gradient_entries, interpolation_entries;
};

Built built(const std::string& cloud, const std::string& extra = "") {
  const auto w = testing::build_from_text(scene_with_cloud(cloud, extra));
  const Body& b = *w.world->bodies[0];
  return {static_cast<double>(b.size()), static_cast<double>(b.gradient.col.size()),
          static_cast<double>(b.interpolation.col.size())};
}

void expect_close_to_built(const std::string& cloud, double tolerance) {
  const auto scene = scene::parse_scene(scene_with_cloud(cloud), "test.toml");
  const RunEstimate e = estimate_run(scene);
  const Built b = built(cloud);
  ASSERT_EQ(e.bodies.size(), 1u);
  EXPECT_EQ(e.bodies[0].particles, b.particles) << cloud;  // exact
  const double grad = e.bodies[0].gradient_entries / b.gradient_entries;
  const double interp = e.bodies[0].interpolation_entries / b.interpolation_entries;
  std::cout << "[ model/built ] gradient " << grad << ", interpolation " << interp << " for\n" << cloud << "\n";
  EXPECT_GT(grad, 1.0 / tolerance) << cloud;
  EXPECT_LT(grad, tolerance) << cloud;
  EXPECT_GT(interp, 1.0 / tolerance) << cloud;
  EXPECT_LT(interp, tolerance) << cloud;
}

TEST(Preflight, CountsAreExactAndEntriesFollowTheBuiltOperators) {
  expect_close_to_built(kBlock, 1.6);
  expect_close_to_built(kSphere, 1.6);
  expect_close_to_built(kShell, 1.6);
}

// Runs `text` through run_scene into a fresh folder: the exit code, the log, and
// whether the output folder was created.
struct Outcome {
  int code;
  std::string log;
  bool wrote;
};
Outcome run_text(const std::string& text, RunLimits limits = {}) {
  const auto dir = testing::fresh_dir("preflight");
  const auto scene = scene::parse_scene(text, "bomb.toml");
  RunOptions options;
  options.out_dir = dir / "out";
  options.quiet = true;
  options.limits = limits;
  std::ostringstream log;
  const int code = run_scene(scene, options, log);
  return {code, log.str(), std::filesystem::exists(options.out_dir)};
}

TEST(Preflight, BlockBombIsRefusedByItsKeyBeforeAnythingIsAllocated) {
  const auto r = run_text(scene_with_cloud("generator = \"block\"\nsize = [1, 1, 1]\ncells = [5000, 5000, 5000]"));
  EXPECT_EQ(r.code, kBadInput);
  EXPECT_NE(r.log.find("bomb.toml:"), std::string::npos) << r.log;
  EXPECT_NE(r.log.find("[body.cloud] cells"), std::string::npos) << r.log;
  EXPECT_NE(r.log.find("1.251e+11 particles"), std::string::npos) << r.log;  // 5001^3
  EXPECT_NE(r.log.find("32-bit"), std::string::npos) << r.log;
  EXPECT_FALSE(r.wrote);
}

TEST(Preflight, ShellBombsAreRefusedByTheirKeys) {
  const auto wide = run_text(scene_with_cloud("generator = \"shell\"\nface_cells = 100000"));
  EXPECT_EQ(wide.code, kBadInput);
  EXPECT_NE(wide.log.find("face_cells and layers"), std::string::npos) << wide.log;
  const auto deep = run_text(scene_with_cloud("generator = \"shell\"\nlayers = 1000000"));
  EXPECT_EQ(deep.code, kBadInput);
  EXPECT_NE(deep.log.find("6.146e+09 particles"), std::string::npos) << deep.log;  // 1e6 (6 32^2 + 2)
}

TEST(Preflight, MemoryLimitNamesEstimateAndLimit) {
  RunLimits limits;
  limits.memory_bytes = 1e6;
  const auto r = run_text(scene_with_cloud(kBlock), limits);
  EXPECT_EQ(r.code, kBadInput);
  EXPECT_NE(r.log.find("[body.cloud] cells"), std::string::npos) << r.log;
  EXPECT_NE(r.log.find("more than the 1 MB given by --memory-limit"), std::string::npos) << r.log;
  EXPECT_FALSE(r.wrote);
  limits.memory_bytes = 1e9;  // the same scene fits in 1 GB
  EXPECT_NO_THROW(check_memory(estimate_run(scene::parse_scene(scene_with_cloud(kBlock), "t.toml")), limits));
}

// check_memory's refusal message, or "" (with a test failure) when it does not refuse.
std::string refusal(const RunEstimate& estimate, const RunLimits& limits) {
  try {
    check_memory(estimate, limits);
  } catch (const PreflightError& error) {
    return error.what();
  }
  ADD_FAILURE() << "expected a refusal";
  return "";
}

// The RBC shell refined in-plane at its five layers (only estimated, never built).
const std::string kRefinedShell =
    "generator = \"shell\"\nsemi_axes = [5e-6, 5e-6, 1.5e-6]\nthickness = 0.5e-6\nface_cells = 96\nlayers = 5";

// A refined shell with declared ball supports: refused, and when ellipsoids would fit the
// refusal names the key and what the run would need with them; when they would not, it
// does not.
TEST(Preflight, RefusalNamesEllipsoidSupportsWhenTheyWouldFit) {
  const std::string refined = kRefinedShell;
  const auto scene =
      scene::parse_scene(scene_with_cloud(refined, "[body.rk]\nsupport_shape = \"sphere\"\n"), "shell.toml");
  const RunEstimate e = estimate_run(scene);
  const double with_ellipsoids = e.memory_bytes - (e.bodies[0].memory_bytes - e.bodies[0].memory_bytes_with_ellipsoids);
  ASSERT_LT(with_ellipsoids, 0.8 * e.memory_bytes);  // spheres on this shell cost more
  RunLimits limits;
  limits.memory_bytes = 0.5 * (with_ellipsoids + e.memory_bytes);
  const std::string fits = refusal(e, limits);
  EXPECT_NE(fits.find("[body.rk] support_shape = \"ellipsoid\" (about "), std::string::npos) << fits;
  limits.memory_bytes = 0.5 * with_ellipsoids;  // neither fits
  const std::string neither = refusal(e, limits);
  EXPECT_FALSE(neither.empty());
  EXPECT_EQ(neither.find("support_shape"), std::string::npos) << neither;
  // Declared ellipsoids: the estimate is the one offered above.
  const auto declared = scene::parse_scene(scene_with_cloud(refined, "[body.rk]\nsupport_shape = \"ellipsoid\"\n"),
                                           "shell.toml");
  EXPECT_DOUBLE_EQ(estimate_run(declared).memory_bytes, with_ellipsoids);
}

// support_shape = "auto" (the default): ellipsoids where a ball would hold more than
// kAutoEllipsoidRowRatio times their particles, balls elsewhere; the pre-flight and the
// build decide alike, and the estimate is the declared shape's.
TEST(Preflight, AutoSupportsAreEllipsoidsWhereBallsWouldOverreach) {
  const auto shape_of = [](const std::string& cloud) {
    const auto scene = scene::parse_scene(scene_with_cloud(cloud), "auto.toml");
    const RunEstimate automatic = estimate_run(scene);
    const std::string shape = automatic.bodies[0].support_shape;
    // The build resolves it the same way.
    const bool ellipsoid = rk_settings(scene.bodies[0]).shape == rk::SupportShape::Ellipsoid;
    EXPECT_EQ(ellipsoid ? "ellipsoid" : "sphere", shape) << cloud;
    // The estimate is that of the declared shape.
    const auto declared = scene::parse_scene(
        scene_with_cloud(cloud, "[body.rk]\nsupport_shape = \"" + shape + "\"\n"), "declared.toml");
    EXPECT_DOUBLE_EQ(estimate_run(declared).memory_bytes, automatic.memory_bytes) << cloud;
    return shape;
  };
  EXPECT_EQ(shape_of(kBlock), "sphere");
  EXPECT_EQ(shape_of(kSphere), "sphere");
  EXPECT_EQ(shape_of(kShell), "sphere");  // the RBC shell at face_cells = 12: cells as wide as the layers
  EXPECT_EQ(shape_of(kRefinedShell), "ellipsoid");  // in-plane spacing a third of the layers'
  // A block refined in its plane only: its spacing across is 10 times its spacing along.
  EXPECT_EQ(shape_of("generator = \"block\"\nsize = [1, 1, 1]\ncells = [100, 100, 10]"), "ellipsoid");
  EXPECT_EQ(shape_of("generator = \"block\"\nsize = [1, 1, 0.25]\ncells = [20, 20, 5]"), "sphere");
}

// On a built body: a thin block with "auto" has the ellipsoids' operators exactly, and
// they are shorter than the balls'.
TEST(Preflight, AutoSupportsBuildTheResolvedShape) {
  const std::string thin = "generator = \"block\"\nsize = [1, 1, 0.5]\ncells = [20, 20, 2]";
  const Built automatic = built(thin);
  const Built ellipsoids = built(thin, "[body.rk]\nsupport_shape = \"ellipsoid\"\n");
  const Built balls = built(thin, "[body.rk]\nsupport_shape = \"sphere\"\n");
  EXPECT_EQ(automatic.gradient_entries, ellipsoids.gradient_entries);
  EXPECT_EQ(automatic.interpolation_entries, ellipsoids.interpolation_entries);
  EXPECT_LT(ellipsoids.gradient_entries, 0.5 * balls.gradient_entries);
}

// A relaxation with nested levels: the estimate lists the particles of each level it
// runs first, and `rkpm check` prints them.
TEST(Preflight, NestedLevelsAreListedWithTheirParticles) {
  const std::string text = testing::read_text(std::filesystem::path(RKPM_SOURCE_DIR) / "examples/rbc/rbc.toml");
  const auto levels_at = [&](const std::string& face_cells) {
    std::string refined = text;
    refined.replace(refined.find("face_cells = 32"), 15, "face_cells = " + face_cells);
    const auto scene = scene::parse_scene(refined, "rbc.toml");
    const RunEstimate e = estimate_run(scene);
    std::ostringstream printed;
    print_estimate(printed, scene, e, RunLimits{}, ".");
    return std::pair{e.level_particles, printed.str()};
  };
  const auto [shipped, shipped_text] = levels_at("32");
  EXPECT_EQ(shipped, (std::vector<double>{4330, 12010}));
  EXPECT_NE(shipped_text.find("nested levels, relaxed first: 4330 12010 particles"), std::string::npos) << shipped_text;
  // Refined: two coarser levels put first (nested_level_factors).
  EXPECT_EQ(levels_at("182").first, (std::vector<double>{8680, 34690, 138730, 389890}));
  // No levels: nothing listed.
  const auto block = scene::parse_scene(scene_with_cloud(kBlock), "block.toml");
  std::ostringstream printed;
  print_estimate(printed, block, estimate_run(block), RunLimits{}, ".");
  EXPECT_EQ(printed.str().find("nested levels"), std::string::npos);
}

// A distributed run: a rank builds its share of the operator rows and keeps the whole
// state, and the ranks of one node share its memory.
TEST(Preflight, RanksDivideTheOperatorsAndShareTheNodesMemory) {
  const auto scene = scene::parse_scene(scene_with_cloud(kBlock), "t.toml");
  const double one = estimate_run(scene, 1, 1).memory_bytes;
  const double two = estimate_run(scene, 2, 1).memory_bytes;
  const double four = estimate_run(scene, 4, 1).memory_bytes;
  EXPECT_LT(four, two);
  EXPECT_LT(two, one);
  // one - four = (3/4) operators, one - two = (1/2) operators: whatever the state costs.
  EXPECT_NEAR((one - four) / (one - two), 1.5, 1e-12);

  const RunEstimate node = estimate_run(scene, 4, 4);
  EXPECT_EQ(node.memory_bytes, four);
  EXPECT_EQ(node.node_memory_bytes(), 4.0 * four);
  RunLimits limits;
  limits.memory_bytes = 2.0 * four;  // room for two of the four ranks
  EXPECT_NO_THROW(check_memory(estimate_run(scene, 4, 1), limits));
  const std::string what = refusal(node, limits);  // four ranks on the node do not fit
  EXPECT_NE(what.find("for the 4 ranks on this node"), std::string::npos) << what;
  EXPECT_NE(what.find("or fewer ranks per node"), std::string::npos) << what;
}

TEST(Preflight, OutputLargerThanTheFreeSpaceIsRefusedByEvery) {
  const std::string dynamic = R"([scene]
name = "frames"
[integrator]
t_end = 1.0
[output]
every = 0.001
[[body]]
name = "body"
density = 1000
[body.cloud]
)" + kBlock + R"(
[body.material]
model = "mooney_rivlin"
c1 = 400
lambda = 2000
)";
  const auto scene = scene::parse_scene(dynamic, "frames.toml");
  const RunEstimate e = estimate_run(scene);
  ASSERT_TRUE(e.frames.has_value());
  EXPECT_EQ(*e.frames, 1002.0);  // the first, one per `every`, the last
  const double points = 13.0 * 7.0 * 4.0, cells = 12.0 * 6.0 * 3.0;
  EXPECT_DOUBLE_EQ(e.frame_bytes, points * 200.0 + cells * 81.0);
  // With a step of 0.01 s the run takes 100 steps: 102 frames, not 1002.
  EXPECT_EQ(frames_expected(scene, e, 0.01), 102.0);
  EXPECT_EQ(frames_expected(scene, e, 1e-5), 1002.0);
  EXPECT_EQ(frames_expected(scene, e, std::nullopt), 2.0);  // step unknown: the first and last
  EXPECT_EQ(frames_expected(scene, e, 1e-5, 40), 42.0);     // --max-steps 40
  RunLimits limits;
  limits.disk_bytes = 50.0 * e.frame_bytes;
  try {
    check_disk(scene, e, 102.0, limits, "out");
    FAIL() << "not refused";
  } catch (const PreflightError& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("frames.toml:6: [output] every"), std::string::npos) << what;
    EXPECT_NE(what.find("102 frames"), std::string::npos) << what;
  }
  EXPECT_NO_THROW(check_disk(scene, e, 2.0, limits, "out"));
}

TEST(Preflight, GeneratorsCheckTheirCountsInSixtyFourBits) {
  particles::BlockSpec block;
  block.cells = {5000, 5000, 5000};
  EXPECT_THROW(particles::make_block(block), particles::CloudError);
  particles::ShellSpec shell;
  shell.face_cells = 100000;
  EXPECT_THROW(particles::make_shell(shell), particles::CloudError);
  particles::SphereSpec sphere;
  sphere.cells = 2000;
  EXPECT_THROW(particles::make_sphere(sphere), particles::CloudError);
}

TEST(Preflight, ByteSizes) {
  EXPECT_EQ(parse_byte_size("8G"), 8e9);
  EXPECT_EQ(parse_byte_size("512M"), 512e6);
  EXPECT_EQ(parse_byte_size("2e9"), 2e9);
  EXPECT_EQ(parse_byte_size("1.5KB"), 1500.0);
  EXPECT_THROW(parse_byte_size("lots"), std::invalid_argument);
  EXPECT_THROW(parse_byte_size("-1G"), std::invalid_argument);
  EXPECT_THROW(parse_byte_size("8Q"), std::invalid_argument);
  EXPECT_EQ(human_bytes(1.5e9), "1.5 GB");
}

TEST(Preflight, EmptySceneNameIsRefused) {
  try {
    scene::parse_scene("[scene]\nname = \"\"\n[integrator]\nmode = \"relax\"\n", "noname.toml");
    FAIL() << "accepted";
  } catch (const scene::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("noname.toml:2: [scene] name"), std::string::npos) << e.what();
  }
  EXPECT_THROW(scene::parse_scene("[scene]\nname = \"../up\"\n[integrator]\nmode = \"relax\"\n", "t.toml"),
               scene::SceneError);
}

}  // namespace
}  // namespace rkpm::sim
