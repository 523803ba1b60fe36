// [body.rk] stabilization_reference_thickness: on a shell of wall thickness T the
// stabilization coefficient is alpha (T / T_ref)^2 (docs/theory/numerics.md), so a
// scene given for one wall keeps the stabilization's weight against the wall's bending
// at another; a cloud without a wall refuses the key with its file and line.
#include "sim_fixtures.hpp"

#include "rkpm/sim/build.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <string>
#include <vector>

namespace {

using rkpm::sim::testing::build_from_text;

std::string shell_scene(double thickness, const std::string& rk_keys) {
  return fmt::format(R"(
[scene]
name = "stabilized_shell"
[integrator]
mode = "relax"
[[body]]
name = "wall"
density = 1000.0
[body.cloud]
generator = "shell"
semi_axes = [5e-6, 5e-6, 1.5e-6]
thickness = {}
face_cells = 6
layers = 3
[body.rk]
{}
[body.material]
model = "neo_hookean"
mu = 1e4
lambda = 1e5
)",
                     thickness, rk_keys);
}

std::vector<double> weights(const std::string& toml) {
  const auto sw = build_from_text(toml);
  return sw.world->bodies.front()->stabilization.weight;
}

// The message of the SetupError that building `toml` raises; "" if it builds.
std::string setup_error(const std::string& toml, const std::string& name = "test.toml") {
  try {
    build_from_text(toml, name);
  } catch (const rkpm::sim::SetupError& e) {
    return e.what();
  }
  return "";
}

// Each scaled weight over the unscaled one at the same particle is `ratio`.
void expect_ratio(const std::vector<double>& scaled, const std::vector<double>& unscaled, double ratio) {
  ASSERT_EQ(scaled.size(), unscaled.size());
  ASSERT_FALSE(scaled.empty());
  for (std::size_t i = 0; i < scaled.size(); ++i) EXPECT_NEAR(scaled[i] / unscaled[i], ratio, 1e-13) << "particle " << i;
}

TEST(StabilizationThickness, ScalesTheCoefficientAsTheSquareOfTheWallThickness) {
  const auto scaled = weights(shell_scene(0.75e-6, "stabilization = 0.1\nstabilization_reference_thickness = 0.5e-6"));
  const auto given = weights(shell_scene(0.75e-6, "stabilization = 0.225"));
  ASSERT_EQ(scaled.size(), given.size());
  for (std::size_t i = 0; i < scaled.size(); ++i) EXPECT_NEAR(scaled[i], given[i], 1e-14 * given[i]) << "particle " << i;
  expect_ratio(scaled, weights(shell_scene(0.75e-6, "stabilization = 0.1")), 2.25);
}

TEST(StabilizationThickness, ScalesAThinnerWallDownAsWell) {
  const auto scaled = weights(shell_scene(0.3e-6, "stabilization = 0.1\nstabilization_reference_thickness = 0.5e-6"));
  expect_ratio(scaled, weights(shell_scene(0.3e-6, "stabilization = 0.1")), 0.36);
}

TEST(StabilizationThickness, AReferenceTenTimesOffTheWallIsRefusedAsAUnitSlip) {
  const std::string what = setup_error(shell_scene(0.5e-6, "stabilization_reference_thickness = 0.5"));
  ASSERT_FALSE(what.empty()) << "a reference of 0.5 m for a 0.5 um wall was accepted";
  EXPECT_NE(what.find("stabilization_reference_thickness = 0.5"), std::string::npos) << what;
  EXPECT_NE(what.find("within a factor 10 of the wall's (5e-07 m)"), std::string::npos) << what;
}

TEST(StabilizationThickness, LeavesTheReferenceWallUnchangedBitForBit) {
  EXPECT_EQ(weights(shell_scene(0.5e-6, "stabilization = 0.1\nstabilization_reference_thickness = 0.5e-6")),
            weights(shell_scene(0.5e-6, "stabilization = 0.1")));
}

TEST(StabilizationThickness, ACloudWithoutAWallRefusesTheKeyWithItsLine) {
  const std::string block = R"(
[scene]
name = "block"
[integrator]
mode = "relax"
[[body]]
name = "b"
density = 1000.0
[body.cloud]
generator = "block"
size = [1e-6, 1e-6, 1e-6]
cells = [3, 3, 3]
[body.rk]
stabilization_reference_thickness = 0.5e-6
[body.material]
model = "neo_hookean"
mu = 1e4
lambda = 1e5
)";
  const std::string what = setup_error(block, "block.toml");
  ASSERT_FALSE(what.empty()) << "a block accepted stabilization_reference_thickness";
  EXPECT_NE(what.find("block.toml:14"), std::string::npos) << what;
  EXPECT_NE(what.find("stabilization_reference_thickness = 5e-07"), std::string::npos) << what;
  EXPECT_NE(what.find("generator = \"shell\", not \"block\""), std::string::npos) << what;
}

}  // namespace
