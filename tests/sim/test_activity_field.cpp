// The activity field of an active LCE shell (seed Eq. 1 with a spatially varying zeta):
// each profile key of [body.material] gives the documented per-particle value.
#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/build.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace {

using rkpm::Vec3;

// One LCE body named `body` on the cloud `cloud_keys` with the activity `material_keys`.
std::string lce_scene(const std::string& body, const std::string& cloud_keys, const std::string& material_keys) {
  return fmt::format(R"(
[scene]
name = "activity"
[integrator]
mode = "relax"
[[body]]
name = "{}"
density = 1000.0
[body.cloud]
{}
[body.material]
model = "lce"
mu = 1e4
bulk = 1e5
{}
[body.director]
initial = "surface_normal"
boundary = "normal"
)",
                     body, cloud_keys, material_keys);
}

std::string shell_scene(const std::string& activity_keys, double thickness = 0.5e-6) {
  return lce_scene("cell",
                   fmt::format("generator = \"shell\"\nsemi_axes = [5e-6, 5e-6, 1.5e-6]\nthickness = {}\n"
                               "face_cells = 6\nlayers = 3",
                               thickness),
                   activity_keys);
}

// An LCE ball (no inner or outer surface, no wall thickness) with `material_keys`; its
// material keys start on line 17 of the text.
std::string ball_scene(const std::string& material_keys) {
  return lce_scene("ball", "generator = \"sphere\"\nradius = 1e-6\ncells = 4", material_keys);
}

// zeta_L of every particle: the reference amplitude times the relative field.
std::vector<double> zeta_field(const rkpm::sim::Body& body) {
  const auto& lce = std::get<rkpm::materials::lce::BodyMaterial>(body.material);
  std::vector<double> zeta(body.size(), lce.model.zeta);
  for (std::size_t i = 0; i < lce.activity.size(); ++i) zeta[i] = lce.model.zeta * lce.activity[i];
  return zeta;
}

TEST(ActivityField, RadialFaceProfilePlusRimBand) {
  const auto world = rkpm::sim::build_world(rkpm::scene::parse_scene(
      shell_scene("zeta = -8e3\nzeta_rim = 3e3\nzeta_rim_power = 4\nzeta_profile = \"radial\"\nzeta_power = 3"),
      "activity.toml"));
  const auto& body = *world->bodies.front();
  const auto zeta = zeta_field(body);
  // The shell is centred at the origin with its axis along z, so rho = |(X, Y)| / max.
  double largest = 0.0;
  for (const auto& X : body.cloud.X) largest = std::max(largest, std::hypot(X.x(), X.y()));
  double worst = 0.0, centre = 0.0, rim = 0.0;
  for (std::size_t i = 0; i < body.size(); ++i) {
    const Vec3& X = body.cloud.X[i];
    const double rho = std::hypot(X.x(), X.y()) / largest;
    const double c = rkpm::materials::lce::material_of(body)->director.h0[i].z();
    const double expected = -8e3 * std::pow(1.0 - rho * rho, 3.0) + 3e3 * std::pow(1.0 - c * c, 2.0);
    worst = std::max(worst, std::abs(zeta[i] - expected));
    if (rho < 0.1) centre = zeta[i];
    if (rho > 0.999) rim = zeta[i];
  }
  EXPECT_LT(worst, 1e-9);
  // Contractile at the centre of the faces, extensile on the equator.
  EXPECT_LT(centre, -7e3);
  EXPECT_GT(rim, 2.9e3);
}

TEST(ActivityField, InnerLayerConfinesTheFaceActivityButNotTheRim) {
  const auto world = rkpm::sim::build_world(rkpm::scene::parse_scene(
      shell_scene("zeta = -8e3\nzeta_rim = 3e3\nzeta_profile = \"axial\"\nzeta_layer = \"inner\""), "activity.toml"));
  const auto& body = *world->bodies.front();
  const auto zeta = zeta_field(body);
  const auto outer = body.cloud.surface_bit("outer"), inner = body.cloud.surface_bit("inner");
  int checked_outer = 0, checked_inner = 0;
  for (std::size_t i = 0; i < body.size(); ++i) {
    const double c = rkpm::materials::lce::material_of(body)->director.h0[i].z();
    const double rim = 3e3 * (1.0 - c * c);
    if (body.cloud.surface_mask[i] & outer) {  // outer half: the rim term only
      EXPECT_NEAR(zeta[i], rim, 1e-9);
      ++checked_outer;
    } else if (body.cloud.surface_mask[i] & inner) {  // inner half: both
      EXPECT_NEAR(zeta[i], -8e3 * std::pow(c * c, 1.0) + rim, 1e-9);
      ++checked_inner;
    }
  }
  EXPECT_GT(checked_outer, 50);
  EXPECT_GT(checked_inner, 50);
}

TEST(ActivityField, RimBendingLayerHasOppositeSignsInTheTwoHalves) {
  const auto world = rkpm::sim::build_world(rkpm::scene::parse_scene(
      shell_scene("zeta_rim = 3e3\nzeta_rim_power = 1\nzeta_rim_layer = \"bending\""), "activity.toml"));
  const auto& body = *world->bodies.front();
  const auto zeta = zeta_field(body);
  const auto outer = body.cloud.surface_bit("outer"), inner = body.cloud.surface_bit("inner");
  for (std::size_t i = 0; i < body.size(); ++i) {
    const double c = rkpm::materials::lce::material_of(body)->director.h0[i].z();
    const double rim = 3e3 * std::sqrt(std::max(0.0, 1.0 - c * c));
    if (body.cloud.surface_mask[i] & outer) {
      EXPECT_NEAR(zeta[i], -rim, 1e-9);
    } else if (body.cloud.surface_mask[i] & inner) {
      EXPECT_NEAR(zeta[i], rim, 1e-9);
    }
  }
}

TEST(ActivityField, RimActivityAloneUsesItAsTheReferenceAmplitude) {
  const auto world = rkpm::sim::build_world(
      rkpm::scene::parse_scene(shell_scene("zeta_rim = 2e3\nzeta_rim_power = 2"), "activity.toml"));
  const auto& body = *world->bodies.front();
  const auto zeta = zeta_field(body);
  for (std::size_t i = 0; i < body.size(); ++i) {
    const double c = rkpm::materials::lce::material_of(body)->director.h0[i].z();
    EXPECT_NEAR(zeta[i], 2e3 * (1.0 - c * c), 1e-9);
  }
}

// zeta_fold adds its own, narrower band with its own layer (here a bending moment, +
// in the inner half and - in the outer); on the 0.3 um wall with the amplitudes for
// 0.5 um its bending is scaled by 0.6 like every layer activity's. Alone it is the
// reference amplitude, in the outer half of the wall by default.
TEST(ActivityField, FoldBandBendsTheWallOutwardInItsOwnBand) {
  for (const double thickness : {0.5e-6, 0.3e-6}) {
    const auto world = rkpm::sim::build_world(rkpm::scene::parse_scene(
        shell_scene("zeta_rim = 3e3\nzeta_rim_power = 2\nzeta_rim_layer = \"outer\"\nzeta_fold = 2e3\n"
                    "zeta_fold_power = 16\nzeta_fold_layer = \"bending\"\nzeta_reference_thickness = 0.5e-6",
                    thickness),
        "activity.toml"));
    const auto& body = *world->bodies.front();
    const auto zeta = zeta_field(body);
    const double scale = thickness / 0.5e-6;
    const auto outer = body.cloud.surface_bit("outer"), inner = body.cloud.surface_bit("inner");
    int equatorial = 0;
    for (std::size_t i = 0; i < body.size(); ++i) {
      const double c = rkpm::materials::lce::material_of(body)->director.h0[i].z();
      const double s2 = 1.0 - c * c, fold = 2e3 * std::pow(s2, 8.0);
      if (body.cloud.surface_mask[i] & outer) {  // outer half: all of the rim, the fold growing it
        EXPECT_NEAR(zeta[i], 3e3 * s2 * (0.5 + 0.5 * scale) - scale * fold, 1e-9);
      } else if (body.cloud.surface_mask[i] & inner) {
        EXPECT_NEAR(zeta[i], 3e3 * s2 * (0.5 - 0.5 * scale) + scale * fold, 1e-9);
      }
      if (s2 > 0.99 && (body.cloud.surface_mask[i] & inner)) ++equatorial;
    }
    EXPECT_GT(equatorial, 5);  // the band is sampled where it matters
  }
  const auto alone = rkpm::sim::build_world(
      rkpm::scene::parse_scene(shell_scene("zeta_fold = 2e3\nzeta_fold_power = 4"), "activity.toml"));
  const auto& body = *alone->bodies.front();
  const auto zeta = zeta_field(body);
  const auto outer = body.cloud.surface_bit("outer"), inner = body.cloud.surface_bit("inner");
  double largest = 0.0;
  for (std::size_t i = 0; i < body.size(); ++i) {
    const double c = rkpm::materials::lce::material_of(body)->director.h0[i].z();
    if (body.cloud.surface_mask[i] & outer) EXPECT_NEAR(zeta[i], 2e3 * std::pow(1.0 - c * c, 2.0), 1e-9);
    if (body.cloud.surface_mask[i] & inner) EXPECT_NEAR(zeta[i], 0.0, 1e-9);
    largest = std::max(largest, std::abs(zeta[i]));
  }
  EXPECT_GT(largest, 1.9e3);  // a field, not the empty "uniform" one
}

// zeta_reference_thickness: a wall of 0.3 um with the amplitudes given for 0.5 um keeps
// the mean of each layer factor over the two halves (the in-plane growth) and scales
// their difference (the bending) by 0.6.
TEST(ActivityField, ReferenceThicknessScalesTheBendingPartAndKeepsTheMean) {
  const std::string keys = "zeta = -8e3\nzeta_profile = \"axial\"\nzeta_power = 2\nzeta_layer = \"inner\"\n"
                           "zeta_rim = 3e3\nzeta_rim_layer = \"bending\"\nzeta_reference_thickness = 0.5e-6";
  const auto world = rkpm::sim::build_world(rkpm::scene::parse_scene(shell_scene(keys, 0.3e-6), "activity.toml"));
  const auto& body = *world->bodies.front();
  const auto zeta = zeta_field(body);
  const auto outer = body.cloud.surface_bit("outer"), inner = body.cloud.surface_bit("inner");
  const double scale = 0.3 / 0.5;
  // side = 1 in the inner half, 0 in the outer half, 1/2 on the mid-surface.
  auto expected = [&](std::size_t i, double side) {
    const double c = rkpm::materials::lce::material_of(body)->director.h0[i].z();
    return -8e3 * c * c * (0.5 + scale * (side - 0.5)) + 3e3 * (1.0 - c * c) * scale * (2.0 * side - 1.0);
  };
  int inner_count = 0, outer_count = 0;
  for (std::size_t i = 0; i < body.size(); ++i) {
    if (body.cloud.surface_mask[i] & inner) {
      EXPECT_NEAR(zeta[i], expected(i, 1.0), 1e-9);
      ++inner_count;
    } else if (body.cloud.surface_mask[i] & outer) {
      EXPECT_NEAR(zeta[i], expected(i, 0.0), 1e-9);
      ++outer_count;
    } else {  // the middle layer (3 layers): on the mid-surface
      EXPECT_NEAR(zeta[i], expected(i, 0.5), 1e-9);
    }
  }
  EXPECT_GT(inner_count, 50);
  EXPECT_GT(outer_count, 50);
}

// The layer of a generated shell's particle (0 = inner surface ... layers - 1 = outer):
// layer k is the ellipsoid with semi-axes a - T (1 - k / (layers - 1)).
int shell_layer(const Vec3& X, const Vec3& semi_axes, double thickness, int layers) {
  int best = 0;
  double best_miss = 1e300;
  for (int k = 0; k < layers; ++k) {
    const Vec3 axes = (semi_axes.array() - thickness * (1.0 - double(k) / (layers - 1))).matrix();
    const double miss = std::abs(X.cwiseQuotient(axes).squaredNorm() - 1.0);
    if (miss < best_miss) {
      best_miss = miss;
      best = k;
    }
  }
  return best;
}

// zeta_layer = "inner" on a 5-layer wall: the two inner layers carry zeta, the two outer
// ones nothing, and every particle of the middle layer half of it. The generated layers
// are not offset surfaces, so the middle layer is not equidistant from the two surfaces'
// nearest particles (0.46-0.54 of the way through a 0.5 um wall, 0.45-0.55 at 0.75 um);
// it was once given wholly to one half, all but 130 of its 6,146 particles in the RBC
// scene, so that a half-wall driver acted on 2.77 layers' worth of particles, not 2.5.
TEST(ActivityField, TheMiddleLayerOfAnOddWallCarriesHalfAHalfWallActivity) {
  const Vec3 semi_axes(5e-6, 5e-6, 1.5e-6);
  for (const double thickness : {0.3e-6, 0.5e-6, 0.75e-6}) {
    const auto world = rkpm::sim::build_world(rkpm::scene::parse_scene(
        lce_scene("cell",
                  fmt::format("generator = \"shell\"\nsemi_axes = [5e-6, 5e-6, 1.5e-6]\nthickness = {}\n"
                              "face_cells = 12\nlayers = 5",
                              thickness),
                  "zeta = -8e3\nzeta_layer = \"inner\""),
        "activity.toml"));
    const auto& body = *world->bodies.front();
    const auto zeta = zeta_field(body);
    std::vector<int> count(5, 0);
    for (std::size_t i = 0; i < body.size(); ++i) {
      const int k = shell_layer(body.cloud.X[i], semi_axes, thickness, 5);
      const double expected = k < 2 ? -8e3 : (k == 2 ? -4e3 : 0.0);
      EXPECT_EQ(zeta[i], expected) << "thickness " << thickness << ", particle " << i << " in layer " << k;
      ++count[static_cast<std::size_t>(k)];
    }
    for (int k = 0; k < 5; ++k) EXPECT_EQ(count[static_cast<std::size_t>(k)], 6 * 12 * 12 + 2) << "layer " << k;
  }
}

// At the reference thickness the scaled field is the unscaled one, bit for bit: the
// example scenes that declare the key keep their results at their own thickness.
TEST(ActivityField, AtTheReferenceThicknessTheFieldIsUnchanged) {
  const std::string keys = "zeta = -8e3\nzeta_profile = \"radial\"\nzeta_layer = \"inner\"\n"
                           "zeta_rim = 3e3\nzeta_rim_layer = \"outer\"";
  const auto plain = rkpm::sim::build_world(rkpm::scene::parse_scene(shell_scene(keys), "activity.toml"));
  const auto scaled = rkpm::sim::build_world(
      rkpm::scene::parse_scene(shell_scene(keys + "\nzeta_reference_thickness = 0.5e-6"), "activity.toml"));
  EXPECT_EQ(zeta_field(*plain->bodies.front()), zeta_field(*scaled->bodies.front()));
}

// zeta_rim_fold_share = f multiplies the rim's amplitude by (1 - f) + f (T / T_ref)^3
// and leaves the face activity alone: with f = 0.4 the rim at 0.75 um is 1.95 times
// (0.6 + 0.4 * 3.375) what it is at T_ref = 0.5 um, at 0.3 um 0.6864 times (0.6 + 0.4 * 0.216).
TEST(ActivityField, FoldShareScalesTheRimWithTheCubeOfTheThickness) {
  const std::string keys = "zeta = -8e3\nzeta_profile = \"axial\"\nzeta_rim = 3e3\nzeta_reference_thickness = 0.5e-6";
  for (const auto& [thickness, factor] : {std::pair{0.75e-6, 1.95}, std::pair{0.3e-6, 0.6864}}) {
    const auto plain = rkpm::sim::build_world(rkpm::scene::parse_scene(shell_scene(keys, thickness), "activity.toml"));
    const auto folded = rkpm::sim::build_world(rkpm::scene::parse_scene(
        shell_scene(keys + "\nzeta_rim_fold_share = 0.4", thickness), "activity.toml"));
    const auto& body = *folded->bodies.front();
    const auto zeta_plain = zeta_field(*plain->bodies.front()), zeta_folded = zeta_field(body);
    for (std::size_t i = 0; i < body.size(); ++i) {
      const double c = rkpm::materials::lce::material_of(body)->director.h0[i].z();
      const double rim = 3e3 * (1.0 - c * c), face = -8e3 * c * c;
      EXPECT_NEAR(zeta_plain[i], face + rim, 1e-9);
      EXPECT_NEAR(zeta_folded[i], face + factor * rim, 1e-9);
    }
  }
}

// Builds the scene `text` (named `file`) and checks that it fails with a SetupError whose
// message contains every one of `fragments`.
void expect_setup_error(const std::string& text, const std::string& file, const std::vector<std::string>& fragments) {
  try {
    rkpm::sim::build_world(rkpm::scene::parse_scene(text, file));
    FAIL() << "expected a SetupError";
  } catch (const rkpm::sim::SetupError& e) {
    for (const auto& fragment : fragments)
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(ActivityField, FoldShareWithoutAReferenceThicknessIsASetupErrorNamingTheKey) {
  expect_setup_error(shell_scene("zeta_rim = 3e3\nzeta_rim_fold_share = 0.4"), "shell.toml",
                     {"shell.toml:20", "zeta_rim_fold_share = 0.4", "zeta_reference_thickness"});
}

TEST(ActivityField, ReferenceThicknessWithoutAShellIsASetupErrorNamingTheKey) {
  expect_setup_error(ball_scene("zeta = -1e3\nzeta_reference_thickness = 0.5e-6"), "ball.toml",
                     {"ball.toml:18", "zeta_reference_thickness"});
}

TEST(ActivityField, LayerOnASolidBodyIsASetupErrorNamingTheKey) {
  expect_setup_error(ball_scene("zeta = -1e3\nzeta_layer = \"inner\""), "ball.toml",
                     {"ball.toml", "zeta_layer = \"inner\""});
}

}  // namespace
