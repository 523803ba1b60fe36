#include "scene_checks.hpp"

#include "clouds/catalog.hpp"
#include "rkpm/scene/param_registry.hpp"
#include "spelling.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace rkpm::scene {
namespace {

std::vector<std::string> body_names(const Scene& scene) {
  std::vector<std::string> names;
  for (const auto& b : scene.bodies) names.push_back(b.name());
  return names;
}

const BodySpec& named_body(const Scene& scene, const ParamSet& p, const std::string& key,
                           const std::string& name) {
  if (const BodySpec* b = scene.find_body(name)) return *b;
  throw p.error(key, "the name of a declared body: " + list_with_suggestion(name, body_names(scene), true));
}

void check_surface(const ParamSet& p, const std::string& key, const BodySpec& body) {
  std::vector<std::string> valid = body.surfaces();
  valid.push_back("all");
  const std::string& surface = p.text(key);
  if (std::find(valid.begin(), valid.end(), surface) == valid.end()) {
    throw p.error(key, fmt::format("a surface of body \"{}\" (generator = \"{}\"): {}", body.name(),
                                   body.generator(), list_with_suggestion(surface, valid, true)));
  }
}

// `owner` is the body a table belongs to ([[body.boundary]]), or nullptr for
// [[term]] tables, whose surface keys refer to the body named by their `body` key.
void check_references(const ParamSet& p, const ParamTable& table, const Scene& scene, const BodySpec* owner) {
  for (const ParamSpec& spec : table.specs) {
    if (spec.reference == Reference::none || !p.has(spec.name)) continue;
    switch (spec.reference) {
      case Reference::none: break;
      case Reference::body: named_body(scene, p, spec.name, p.text(spec.name)); break;
      case Reference::bodies: {
        const auto& names = p.texts(spec.name);
        for (std::size_t i = 0; i < names.size(); ++i) {
          named_body(scene, p, spec.name, names[i]);
          for (std::size_t j = 0; j < i; ++j) {
            if (names[i] == names[j]) throw p.error(spec.name, fmt::format("different bodies (\"{}\" is named twice)", names[i]));
          }
        }
        break;
      }
      case Reference::surface:
        check_surface(p, spec.name, owner ? *owner : named_body(scene, p, "body", p.text("body")));
        break;
    }
  }
}

void check_tables(const ParamSet& p, const Scene& scene, const BodySpec* owner) {
  const ParamRegistry& registry = ParamRegistry::instance();
  if (const ParamTable* base = registry.section(p.section())) check_references(p, *base, scene, owner);
  if (const ParamTable* variant = registry.variant(p.section(), p.variant())) check_references(p, *variant, scene, owner);
}

void check_unique_names(const Scene& scene) {
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (scene.bodies[i].name() == scene.bodies[j].name()) {
        const ParamSet& p = scene.bodies[i].body;
        throw p.error("name", fmt::format("a unique body name (already used at line {})", scene.bodies[j].body.line("name")));
      }
    }
  }
}

void check_output(Scene& scene) {
  const ParamSet& integrator = scene.integrator;
  ParamSet& output = scene.output;
  if (!integrator.has("t_end")) return;
  const double t_end = integrator.real("t_end");
  if (!output.has("every")) {
    output.set("every", t_end / 50.0, output.table_line(), false);
  } else if (output.real("every") > t_end) {
    throw output.error("every", fmt::format("a frame interval no longer than [integrator] t_end = {} s",
                                            format_value(t_end)));
  }
}

// Nested iteration remakes each body's cloud at a coarser resolution: only a generator
// can do that, an imported mesh cannot be coarsened.
void check_nested_levels(const Scene& scene) {
  if (scene.integrator.reals("nested_levels").empty()) return;
  for (const auto& body : scene.bodies)
    if (!clouds::can_rescale(body))
      throw scene.integrator.error(
          "nested_levels", fmt::format("[] when a body's cloud is imported (body \"{}\", generator = \"{}\" at "
                                       "line {}): only generated clouds can be coarsened",
                                       body.name(), body.generator(), body.cloud.line("generator")));
}

}  // namespace

void check_scene(Scene& scene) {
  check_unique_names(scene);
  for (const auto& body : scene.bodies) {
    for (const auto& boundary : body.boundaries) check_tables(boundary, scene, &body);
  }
  for (const auto& term : scene.terms) check_tables(term.params, scene, nullptr);
  check_output(scene);
  check_nested_levels(scene);
}

}  // namespace rkpm::scene
