// The declaration framework: specs, typed getters and the generated reference.
#include "rkpm/scene/param_registry.hpp"
#include "rkpm/scene/scene.hpp"
#include "scene_text.hpp"

#include <gtest/gtest.h>

#include <set>
#include <sstream>

namespace rkpm::scene {
namespace {

TEST(ParamSpec, RangesHonourOpenAndClosedEnds) {
  const ParamSpec half_open = ParamSpec::real("x", "-").greater_than(0).at_most(1);
  EXPECT_FALSE(half_open.in_range(0.0));
  EXPECT_TRUE(half_open.in_range(1e-300));
  EXPECT_TRUE(half_open.in_range(1.0));
  EXPECT_FALSE(half_open.in_range(1.0 + 1e-15));
  EXPECT_EQ(half_open.range_text(), "in (0, 1]");

  const ParamSpec closed = ParamSpec::real("y", "m").at_least(1).less_than(4);
  EXPECT_TRUE(closed.in_range(1.0));
  EXPECT_FALSE(closed.in_range(4.0));
  EXPECT_EQ(closed.range_text(), "in [1, 4)");
  EXPECT_EQ(closed.expectation(), "a real in [1, 4) [m]");
  EXPECT_EQ(ParamSpec::integer("n").at_least(2).expectation(), "an integer >= 2");
}

TEST(ParamSpec, DefaultTextShowsRequiredValueOrNote) {
  EXPECT_EQ(ParamSpec::real("a", "Pa").mark_required().default_text(), "required");
  EXPECT_EQ(ParamSpec::vec3("v", "m").defaults(Vec3(0, 0, 1)).default_text(), "[0, 0, 1]");
  EXPECT_EQ(ParamSpec::real("c", "m").absent_means("3 s0").default_text(), "3 s0");
  // A real default written as an integer literal is stored as a real.
  EXPECT_TRUE(std::holds_alternative<double>(*ParamSpec::real("d", "-").defaults(std::int64_t{2}).default_value));
}

TEST(ParamSet, UndeclaredOrMistypedNamesAreProgrammingErrors) {
  const Scene s = parse_scene(testing::kBase, "ok.toml");
  const ParamSet& material = s.bodies[0].material;
  EXPECT_THROW(material.real("mu"), std::logic_error);         // not a Mooney-Rivlin key
  EXPECT_THROW(material.integer("c1"), std::logic_error);      // declared as a real
  EXPECT_THROW(material.vec3("model"), std::logic_error);
  EXPECT_THROW(s.integrator.has("t_ned"), std::logic_error);
  EXPECT_EQ(material.text("model"), "mooney_rivlin");          // a choice reads as text too
  EXPECT_THROW(s.integrator.choice("t_end"), std::logic_error);
}

TEST(ParamSet, ErrorNamesFileLineSectionKeyAndValue) {
  const Scene s = parse_scene(testing::kBase, "ok.toml");
  const SceneError e = s.bodies[0].cloud.error("size", "something else");
  EXPECT_EQ(std::string(e.what()), "ok.toml:9: [body.cloud] size = [1, 1, 1]: expected something else");
  EXPECT_EQ(e.line(), 9);
}

TEST(ParamRegistry, VariantSectionsOfferExactlyTheirVariants) {
  const ParamRegistry& r = ParamRegistry::instance();
  EXPECT_EQ(r.variant_names("body.cloud"), (std::vector<std::string>{"block", "sphere", "shell", "vtu", "gmsh"}));
  EXPECT_EQ(r.variant_names("body.material"), (std::vector<std::string>{"lce", "mooney_rivlin", "neo_hookean", "viscoelastic"}));
  EXPECT_EQ(r.variant_names("term"), (std::vector<std::string>{"body_force", "surface_pressure", "volume_constraint",
                                                               "surface_tension", "contact", "wall_contact"}));
  EXPECT_EQ(r.section("term")->specs.front().choices, r.variant_names("term"));
  EXPECT_EQ(r.section("nonsense"), nullptr);
  EXPECT_EQ(r.variant("body.cloud", "torus"), nullptr);
}

TEST(ParamRegistry, EveryDeclarationIsComplete) {
  std::set<std::string> ids;
  for (const ParamTable& t : ParamRegistry::instance().tables()) {
    EXPECT_TRUE(ids.insert(t.id()).second) << "table declared twice: " << t.id();
    EXPECT_FALSE(t.help.empty()) << t.id();
    std::set<std::string> names;
    for (const ParamSpec& p : t.specs) {
      EXPECT_TRUE(names.insert(p.name).second) << t.id() << ": " << p.name << " declared twice";
      EXPECT_FALSE(p.help_text.empty()) << t.id() << ": " << p.name << " has no help";
      EXPECT_FALSE(p.unit.empty()) << t.id() << ": " << p.name;
      if (p.default_value && (p.min || p.max)) {
        // A default outside its own range would make an empty table invalid.
        std::vector<double> numbers;
        if (const auto* d = std::get_if<double>(&*p.default_value)) numbers = {*d};
        if (const auto* i = std::get_if<std::int64_t>(&*p.default_value)) numbers = {static_cast<double>(*i)};
        if (const auto* v = std::get_if<Vec3>(&*p.default_value)) numbers = {v->x(), v->y(), v->z()};
        if (const auto* l = std::get_if<std::vector<double>>(&*p.default_value)) numbers = *l;
        for (double x : numbers) EXPECT_TRUE(p.in_range(x)) << t.id() << ": default of " << p.name;
      }
    }
  }
  EXPECT_GE(ids.size(), 20u);
}

TEST(PrintParams, TextAndMarkdownListEveryTableAndKey) {
  for (const ParamFormat format : {ParamFormat::text, ParamFormat::markdown}) {
    std::ostringstream out;
    print_params(out, format);
    const std::string text = out.str();
    for (const ParamTable& t : ParamRegistry::instance().tables()) {
      EXPECT_NE(text.find(t.heading()), std::string::npos) << t.heading();
      for (const ParamSpec& p : t.specs) {
        const std::string key = format == ParamFormat::markdown ? "| `" + p.name + "` |" : "  " + p.name + " ";
        EXPECT_NE(text.find(key), std::string::npos) << t.heading() << " " << p.name;
      }
    }
  }
}

TEST(PrintParams, MarkdownRowsShowUnitDefaultAndRange) {
  std::ostringstream out;
  print_params(out, ParamFormat::markdown);
  const std::string md = out.str();
  EXPECT_NE(md.find("| `dt_safety` | real | - | `0.5` | in (0, 1] |"), std::string::npos);
  EXPECT_NE(md.find("| `mu` | real | Pa | required | > 0 |"), std::string::npos);
  EXPECT_NE(md.find("| `cutoff` | real | m | 3 s0 | > 0 |"), std::string::npos);
  EXPECT_NE(md.find("| `kernel` | choice | - | `\"cubic\"` | cubic \\| quintic |"), std::string::npos);
  EXPECT_NE(md.find("Surfaces: `outer` `inner`"), std::string::npos);
}

}  // namespace
}  // namespace rkpm::scene
