// The term catalog (src/terms/catalog.def): the scene registry's [[term]] types are
// the catalog's kinds, in its order; each kind's table reads into its settings
// struct with every key spelled once; build_world creates exactly the declared terms.
#include "sim_fixtures.hpp"

#include "rkpm/scene/param_registry.hpp"
#include "terms/catalog.hpp"
#include "terms/contact/settings.hpp"
#include "terms/wall_contact/settings.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rkpm::sim {
namespace {

std::vector<std::string> catalog_kinds() {
  return {
#define RKPM_TERM(kind) #kind,
#include "terms/catalog.def"
#undef RKPM_TERM
  };
}

TEST(TermCatalog, RegistryTypesAreTheCatalogKindsInOrder) {
  const auto kinds = catalog_kinds();
  ASSERT_FALSE(kinds.empty());
  EXPECT_EQ(scene::ParamRegistry::instance().variant_names("term"), kinds);
  const auto tables = terms::term_tables();
  ASSERT_EQ(tables.size(), kinds.size());
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    EXPECT_EQ(tables[i].selector_value, kinds[i]);
    EXPECT_EQ(tables[i].section, "term");
    EXPECT_FALSE(tables[i].specs.empty()) << kinds[i];
  }
}

const std::string kTwoBlocks = R"([scene]
name = "catalog"
[integrator]
mode = "relax"
[[body]]
name = "a"
density = 1000
[body.cloud]
generator = "block"
size = [1, 1, 1]
cells = [3, 3, 3]
[body.material]
model = "mooney_rivlin"
c1 = 400
lambda = 2000
[[body]]
name = "b"
density = 1000
[body.cloud]
generator = "block"
origin = [0, 0, 1.5]
size = [1, 1, 1]
cells = [3, 3, 3]
[body.material]
model = "mooney_rivlin"
c1 = 400
c2 = 100
lambda = 2000
grade_axis = "x"
grade_a = 2
)";

const std::string kEveryTerm = R"([[term]]
type = "body_force"
body = "a"
acceleration = [0, 0, -9.81]
[[term]]
type = "surface_pressure"
body = "a"
surface = "xmin"
pressure = 10
[[term]]
type = "volume_constraint"
body = "b"
surface = "all"
bulk = 1000
[[term]]
type = "surface_tension"
body = "b"
gamma = 0.01
[[term]]
type = "contact"
bodies = ["b", "a"]
epsilon = 1e-20
s0 = 0.25
beta = [3, 4]
stiffness_law = "linear"
substrate = "b"
[[term]]
type = "wall_contact"
body = "a"
surface = "zmax"
distance = 0.05
pressure = 100
exclusion = 0.5
)";

TEST(TermCatalog, BuildsEveryDeclaredTermByNameInFileOrder) {
  const auto w = testing::build_from_text(kTwoBlocks + kEveryTerm);
  const auto kinds = catalog_kinds();
  ASSERT_EQ(w.world->terms.size(), kinds.size());
  for (std::size_t i = 0; i < kinds.size(); ++i) EXPECT_EQ(w.world->terms[i]->name(), kinds[i]);
}

TEST(TermCatalog, SceneWithoutTermsBuildsNone) {
  const auto w = testing::build_from_text(kTwoBlocks);
  EXPECT_TRUE(w.world->terms.empty());
}

TEST(TermSettings, EveryKeyReachesItsMemberAndDerivedDefaultsAreFilled) {
  const auto w = testing::build_from_text(kTwoBlocks + kEveryTerm);
  const auto contact = w.scene.terms_of("contact");
  ASSERT_EQ(contact.size(), 1u);
  const ContactSettings c = terms::contact::settings_table().read(contact[0]->params);
  EXPECT_EQ(c.bodies, (std::vector<std::string>{"b", "a"}));
  EXPECT_EQ(c.epsilon, 1e-20);
  EXPECT_EQ(c.s0, 0.25);
  EXPECT_DOUBLE_EQ(c.cutoff, 0.75);  // absent: 3 s0
  EXPECT_DOUBLE_EQ(c.skin, 0.125);  // absent: 0.5 s0
  EXPECT_EQ(c.beta[0], 3.0);
  EXPECT_EQ(c.beta[1], 4.0);
  EXPECT_EQ(c.law, StiffnessLaw::linear);
  EXPECT_EQ(c.substrate, "b");
  EXPECT_EQ(c.stiffness_reference, 0.0);  // declared default
  EXPECT_EQ(c.report_surface, "");

  const auto wall = w.scene.terms_of("wall_contact");
  ASSERT_EQ(wall.size(), 1u);
  const WallContactSettings s = terms::wall_contact::settings_table().read(wall[0]->params);
  EXPECT_EQ(s.body, "a");
  EXPECT_EQ(s.surface, "zmax");
  EXPECT_EQ(s.distance, 0.05);
  EXPECT_EQ(s.pressure, 100.0);
  EXPECT_EQ(s.exclusion, 0.5);
  EXPECT_DOUBLE_EQ(s.skin, 0.025);
}

// Every key a table declares is bound to a member: a table whose specs and readers
// disagreed would leave a declared key unread. The binding adds both at once, so the
// count of declared keys is the count of bindings; this checks the registry holds
// exactly the bound tables (no spec added behind the binding's back).
TEST(TermSettings, RegistryTablesAreTheBoundTables) {
  const auto& registry = scene::ParamRegistry::instance();
  EXPECT_EQ(registry.variant("term", "contact")->names(), terms::contact::settings_table().table().names());
  EXPECT_EQ(registry.variant("term", "wall_contact")->names(), terms::wall_contact::settings_table().table().names());
}

}  // namespace
}  // namespace rkpm::sim
