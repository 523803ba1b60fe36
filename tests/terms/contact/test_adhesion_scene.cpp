// The adhesion scene (examples/adhesion, seed section 4.2) at a coarse resolution:
// the cell lands, adheres with a finite contact radius, does not interpenetrate the
// substrate, and the energy ledger closes.
//
// The scene file is read and only its resolution is coarsened (a 10-cell sphere,
// 1,331 particles; a 20 x 20 um block of 16 x 16 x 2 cells, 867 particles). The
// contact length s0 follows the substrate's lateral spacing as in the scene
// (spacing = 1.25 s0), eps keeps the adhesion energy |W(d0)| = 1e-3 J/m^2, and the
// cell starts 200 nm beyond the equilibrium gap 0.6368 s0. Measured at this
// resolution: smallest gap over the run 0.648 s0,
// contact radius 2.63 um (45 particles; 9 within s0 at release), energy error 6.4e-4.
#include "contact_fixtures.hpp"

#include "rkpm/sim/build.hpp"
#include "terms/contact/contact.hpp"
#include "terms/contact/holding.hpp"
#include "rkpm/scene/param_set.hpp"
#include "rkpm/sim/integrator.hpp"
#include "rkpm/sim/output.hpp"

#include <gtest/gtest.h>
#include <fmt/format.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>

namespace rkpm::sim {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Replaces the value of the first line `key = ...` that follows `anchor`.
void set_key(std::string& text, const std::string& anchor, const std::string& key, const std::string& value) {
  const auto from = text.find(anchor);
  ASSERT_NE(from, std::string::npos) << "scene has no '" << anchor << "'";
  std::smatch m;
  const std::string rest = text.substr(from);
  ASSERT_TRUE(std::regex_search(rest, m, std::regex("\\n" + key + " = [^\\n]*"))) << "no key " << key;
  text.replace(from + static_cast<std::size_t>(m.position(0)), static_cast<std::size_t>(m.length(0)),
               "\n" + key + " = " + value);
}

// The scene at the coarse resolution above, with the substrate's lateral cell count
// `substrate_cells` over its 20 um (spacing 20 um / cells), contact length s0, and the
// cell's lowest point `release_gap` above the block (negative: inside it).
std::string coarse_scene(int substrate_cells, double s0, double release_gap) {
  std::string scene = read_text(RKPM_SOURCE_DIR "/examples/adhesion/adhesion.toml");
  EXPECT_FALSE(scene.empty());
  const double W = 1e-3, beta = 1e18;
  const double eps = W / (0.96848 * beta * beta * s0 * s0 * s0 * s0);
  set_key(scene, "[integrator]", "t_end", "8e-6");
  set_key(scene, "name = \"cell\"", "center", fmt::format("[0.0, 0.0, {}]", 4.5e-6 + release_gap + 5e-6));
  set_key(scene, "name = \"cell\"", "cells", "10");
  set_key(scene, "name = \"substrate\"", "origin", "[-10e-6, -10e-6, 0.0]");
  set_key(scene, "name = \"substrate\"", "size", "[20e-6, 20e-6, 4.5e-6]");
  set_key(scene, "name = \"substrate\"", "cells", fmt::format("[{}, {}, 2]", substrate_cells, substrate_cells));
  set_key(scene, "type = \"contact\"", "s0", fmt::format("{}", s0));
  set_key(scene, "type = \"contact\"", "epsilon", fmt::format("{}", eps));
  set_key(scene, "type = \"contact\"", "beta", fmt::format("[{}, {}]", beta, beta));
  return scene;
}

TEST(AdhesionScene, CoarseCellLandsAdheresAndDoesNotInterpenetrate) {
  const double spacing = 20e-6 / 16, s0 = spacing / 1.25;
  const double release_gap = 0.6368 * s0 + 0.2e-6;
  const std::string scene = coarse_scene(16, s0, release_gap);
  auto w = testing::world_from_text(scene);
  const Contact* contact = nullptr;
  for (const auto& t : w.world->terms)
    if (const auto* c = dynamic_cast<const Contact*>(t.get())) contact = c;
  ASSERT_TRUE(contact && contact->has_report());
  Integrator integrator(*w.world, integrator_settings(w.scene));
  integrator.initialize();
  const ContactSample start = contact->sample();
  EXPECT_NEAR(start.min_gap, release_gap, 0.05 * s0);  // the gap measure sees the release gap
  double smallest_gap = start.min_gap;
  int samples = 0;
  const double t_end = 8e-6;
  double next = 0.0;
  ContactSample s;
  while (w.world->time < t_end) {
    integrator.step();
    if (w.world->time >= next) {
      s = contact->sample();
      smallest_gap = std::min(smallest_gap, s.min_gap);
      next += 0.25e-6;
      ++samples;
    }
  }
  s = contact->sample();
  const auto& e = integrator.measure_energy();
  std::printf("%lld steps, %d samples: centroid z %.4f -> %.4f um; smallest gap %.3f s0 (final %.3f s0); contact "
              "radius %.3f um (%lld particles, %lld at release); kinetic %.3g J, dissipated %.3g J; energy error %.2e\n",
              static_cast<long long>(w.world->step), samples, 1e6 * start.centroid.z(), 1e6 * s.centroid.z(),
              smallest_gap / s0, s.min_gap / s0, 1e6 * s.contact_radius, static_cast<long long>(s.contact_particles),
              static_cast<long long>(start.contact_particles),
              e.kinetic, e.dissipated, e.relative_error());
  EXPECT_LT(s.centroid.z(), start.centroid.z() - 0.2e-6);           // landed (and flattened)
  EXPECT_GT(s.contact_radius, 1.5 * spacing);                       // a finite contact patch
  EXPECT_GT(s.contact_particles, 3 * start.contact_particles);      // grown from the first touch
  EXPECT_LT(s.contact_radius, 5e-6);                                // not beyond the cell's radius
  EXPECT_GT(smallest_gap, 0.4 * s0);                                // no interpenetration
  EXPECT_LT(s.min_gap, s0);                                         // still in contact at the end
  EXPECT_LT(e.relative_error(), 2e-3);                              // the ledger closes
  EXPECT_LT(e.kinetic, 0.1 * e.dissipated);                         // settled
  EXPECT_LT(std::hypot(s.centroid.x(), s.centroid.y()), 0.05e-6);   // symmetric scene: no lateral drift
}


// The set-up check (holding.hpp): the substrate's top face is a square grid of spacing
// a, so its widest facing hollow is a / sqrt(2), and the corners push a particle back
// only from within s0: grids below sqrt(2) s0. At a = 1.40 s0 the scene builds; at 1.42 s0
// it is refused, naming s0, the coarse body and its hollow.
TEST(AdhesionScene, TheSetUpRefusesASubstrateTooCoarseForS0) {
  const double spacing = 20e-6 / 16;
  EXPECT_NO_THROW(testing::world_from_text(coarse_scene(16, spacing / 1.40, 0.6368 * spacing / 1.40 + 0.2e-6)));
  const double s0 = spacing / 1.42;
  try {
    testing::world_from_text(coarse_scene(16, s0, 0.6368 * s0 + 0.2e-6));
    FAIL() << "a substrate grid of 1.42 s0 was accepted";
  } catch (const SetupError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(fmt::format("[term] s0 = {}", scene::format_value(s0))), std::string::npos) << what;
    EXPECT_NE(what.find("the surface of body 'substrate' facing 'cell'"), std::string::npos) << what;
    EXPECT_NE(what.find(fmt::format("hollow {:.4g} m = 1.004 s0", spacing / std::sqrt(2.0))), std::string::npos)
        << what;
    EXPECT_NE(what.find("particles of 'cell' would fall through"), std::string::npos) << what;
  }
}

// Only the faces that face the other body count: the block's top towards the cell, its
// bottom towards a point below; its sides (taller than wide here) never.
TEST(AdhesionScene, TheWidestHollowIsTakenOverTheFacesTowardsTheOtherBody) {
  const double spacing = 20e-6 / 16, s0 = spacing / 1.25;
  auto w = testing::world_from_text(coarse_scene(16, s0, 0.6368 * s0 + 0.2e-6));
  const Body& substrate = *w.world->find_body("substrate");
  const SurfaceHollow top = widest_facing_hollow(substrate, reference_centroid(*w.world->find_body("cell")));
  EXPECT_NEAR(top.radius, spacing / std::sqrt(2.0), 1e-12 * spacing);
  EXPECT_NEAR(top.centre.z(), 4.5e-6, 1e-15);
  const SurfaceHollow bottom = widest_facing_hollow(substrate, Vec3(0.0, 0.0, -1.0));
  EXPECT_NEAR(bottom.centre.z(), 0.0, 1e-15);
  const double side = 0.5 * std::hypot(spacing, 4.5e-6 / 2);  // a side face's half-diagonal
  EXPECT_LT(top.radius, side);
  EXPECT_NEAR(widest_facing_hollow(substrate, Vec3(1.0, 0.0, 2.25e-6)).radius, side, 1e-12 * side);
}

// Bodies declared overlapping are found before the first step: the integrator's check
// reaches the contact term's diagnosis, which names the body, the particle and its depth.
TEST(AdhesionScene, ACellDeclaredInsideTheSubstrateIsStoppedBeforeTheFirstStep) {
  const double spacing = 20e-6 / 16, s0 = spacing / 1.25;
  auto w = testing::world_from_text(coarse_scene(16, s0, -1e-6));
  Integrator integrator(*w.world, integrator_settings(w.scene));
  try {
    integrator.initialize();
    FAIL() << "a cell 1 um inside the block started";
  } catch (const BlowUp& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("body 'cell' starts inside body 'substrate'"), std::string::npos) << what;
    EXPECT_NE(what.find("lies 1e-06 m inside"), std::string::npos) << what;
  }
}

// During a run: a cell moved through the top layer between two rebuilds of the pair list
// is reported at the next one; before the move, every rebuild of a landing finds nothing.
TEST(AdhesionScene, ACellPushedThroughTheSurfaceIsDiagnosedAtTheNextRebuild) {
  const double spacing = 20e-6 / 16, s0 = spacing / 1.25;
  auto w = testing::world_from_text(coarse_scene(16, s0, 0.6368 * s0 + 0.2e-6));
  Contact* contact = nullptr;
  for (const auto& t : w.world->terms)
    if (auto* c = dynamic_cast<Contact*>(t.get())) contact = c;
  ASSERT_TRUE(contact);
  Integrator integrator(*w.world, integrator_settings(w.scene));
  integrator.initialize();
  for (int k = 0; k < 20; ++k) integrator.step();
  EXPECT_EQ(contact->diagnose(*w.world), "");
  // The whole cell 2 um down: its lowest particle 2 um - release gap = 1.0 um inside.
  Body& cell = *w.world->find_body("cell");
  for (auto& d : cell.d) d.z() -= 2e-6;
  compute_forces(*w.world);
  const std::string what = contact->diagnose(*w.world);
  EXPECT_NE(what.find("body 'cell' has passed through the surface of body 'substrate'"), std::string::npos) << what;
  EXPECT_NE(what.find("s0/2 = "), std::string::npos) << what;
  // Asked again without a rebuild of the pairs: not measured again.
  EXPECT_EQ(contact->diagnose(*w.world), "");
}

// The winding number behind the diagnosis: inside and outside the block's closed surface.
TEST(AdhesionScene, TheWindingNumberTellsInsideFromOutside) {
  const double spacing = 20e-6 / 16, s0 = spacing / 1.25;
  auto w = testing::world_from_text(coarse_scene(16, s0, 0.6368 * s0 + 0.2e-6));
  const Body& cell = *w.world->find_body("cell");
  const Body& substrate = *w.world->find_body("substrate");
  ContactReport report(cell, substrate, "all", s0, 4 * 3 * s0);
  report.measure();
  EXPECT_TRUE(report.encloses(Vec3(0.3e-6, -0.2e-6, 2e-6)));
  EXPECT_TRUE(report.encloses(Vec3(9.9e-6, 9.9e-6, 4.4e-6)));  // near a corner, inside
  EXPECT_FALSE(report.encloses(Vec3(0.0, 0.0, 4.6e-6)));        // just above the top
  EXPECT_FALSE(report.encloses(Vec3(10.1e-6, 0.0, 2e-6)));      // beside a side
  EXPECT_FALSE(report.encloses(Vec3(0.0, 0.0, -1e-6)));         // below
}


// The frames show each particle's contact force, named after the other body: the
// term's own forces on the physical points, zero on the body the field is not about,
// and, summed over each body, equal and opposite (the pair forces cancel).
TEST(AdhesionScene, FramesShowEachParticlesContactForce) {
  const double spacing = 20e-6 / 16, s0 = spacing / 1.25;
  auto w = testing::world_from_text(coarse_scene(16, s0, 0.5 * s0));
  const Contact* contact = nullptr;
  for (const auto& t : w.world->terms)
    if (const auto* c = dynamic_cast<const Contact*>(t.get())) contact = c;
  ASSERT_NE(contact, nullptr);
  Integrator integrator(*w.world, integrator_settings(w.scene));
  integrator.initialize();
  std::vector<Vec3> positions;
  const io::Frame frame = make_frame(*w.world, CellOutput::Points, positions);
  const auto field = [&](const std::string& name) -> const io::PointField& {
    for (const auto& f : frame.point_fields)
      if (f.name == name) return f;
    ADD_FAILURE() << "the frame has no field " << name;
    return frame.point_fields.front();
  };
  const io::PointField& on_cell = field("contact_force_substrate");
  const io::PointField& on_substrate = field("contact_force_cell");
  ASSERT_EQ(on_cell.components, 3);
  const Body& cell = *w.world->bodies[0];
  const Body& substrate = *w.world->bodies[1];
  ASSERT_EQ(on_cell.tuples(), cell.size() + substrate.size());
  Vec3 sum_cell = Vec3::Zero(), sum_substrate = Vec3::Zero();
  double largest = 0.0;
  std::size_t touching = 0;
  std::size_t lowest = 0;
  for (std::size_t i = 0; i < cell.size(); ++i) {
    if (cell.cloud.X[i].z() < cell.cloud.X[lowest].z()) lowest = i;
    const Vec3 f(&on_cell.values[3 * i]);
    EXPECT_EQ(f, contact->force_on(0)[i]);
    EXPECT_EQ(Vec3(&on_substrate.values[3 * i]), Vec3::Zero());
    sum_cell += f;
    largest = std::max(largest, f.norm());
    touching += f.norm() > 0.0 ? 1 : 0;
  }
  for (std::size_t j = 0; j < substrate.size(); ++j) {
    const std::size_t row = 3 * (cell.size() + j);
    const Vec3 f(&on_substrate.values[row]);
    EXPECT_EQ(f, contact->force_on(1)[j]);
    EXPECT_EQ(Vec3(&on_cell.values[row]), Vec3::Zero());
    sum_substrate += f;
  }
  // The cell starts at a gap of s0 / 2, inside the equilibrium gap (0.64 s0): its
  // lowest particle is pushed up; only the particles within the cutoff feel a force.
  EXPECT_GT(on_cell.values[3 * lowest + 2], 0.0);
  EXPECT_GT(touching, 5u);
  EXPECT_LT(touching, cell.size() / 2);
  EXPECT_LT((sum_cell + sum_substrate).norm(), 1e-12 * largest * static_cast<double>(touching));
}

}  // namespace
}  // namespace rkpm::sim
