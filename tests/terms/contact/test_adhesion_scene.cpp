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
#include "rkpm/sim/integrator.hpp"

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

TEST(AdhesionScene, CoarseCellLandsAdheresAndDoesNotInterpenetrate) {
  std::string scene = read_text(RKPM_SOURCE_DIR "/examples/adhesion/adhesion.toml");
  ASSERT_FALSE(scene.empty());
  const double spacing = 20e-6 / 16, s0 = spacing / 1.25, W = 1e-3, beta = 1e18;
  const double eps = W / (0.96848 * beta * beta * s0 * s0 * s0 * s0);
  const double release_gap = 0.6368 * s0 + 0.2e-6;
  set_key(scene, "[integrator]", "t_end", "8e-6");
  set_key(scene, "name = \"cell\"", "center", fmt::format("[0.0, 0.0, {}]", 4.5e-6 + release_gap + 5e-6));
  set_key(scene, "name = \"cell\"", "cells", "10");
  set_key(scene, "name = \"substrate\"", "origin", "[-10e-6, -10e-6, 0.0]");
  set_key(scene, "name = \"substrate\"", "size", "[20e-6, 20e-6, 4.5e-6]");
  set_key(scene, "name = \"substrate\"", "cells", "[16, 16, 2]");
  set_key(scene, "type = \"contact\"", "s0", fmt::format("{}", s0));
  set_key(scene, "type = \"contact\"", "epsilon", fmt::format("{}", eps));
  set_key(scene, "type = \"contact\"", "beta", fmt::format("[{}, {}]", beta, beta));

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

}  // namespace
}  // namespace rkpm::sim
