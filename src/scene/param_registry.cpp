#include "rkpm/scene/param_registry.hpp"

#include "clouds/catalog.hpp"
#include "materials/catalog.hpp"
#include "tables/tables.hpp"
#include "terms/catalog.hpp"

#include <stdexcept>

namespace rkpm::scene {
namespace {

// The table of a section with variants holds only the selector, whose choices are
// the registered variants: adding a variant adds the choice.
ParamTable selector_section(std::string section, std::string key, const std::vector<ParamTable>& variants,
                            std::string help) {
  std::vector<std::string> names;
  for (const auto& v : variants) names.push_back(v.selector_value);
  ParamTable t;
  t.section = std::move(section);
  t.help = std::move(help);
  t.specs = {ParamSpec::choice(key, names).mark_required().help("Selects the table below that supplies the other keys.")};
  return t;
}

void append(std::vector<ParamTable>& to, std::vector<ParamTable> from) {
  for (auto& t : from) to.push_back(std::move(t));
}

}  // namespace

ParamRegistry::ParamRegistry() {
  append(tables_, tables::run_sections());
  tables_.push_back(tables::body());

  auto generators = clouds::cloud_tables();
  tables_.push_back(selector_section("body.cloud", "generator", generators,
                                     "The body's particle cloud: a generator or an imported mesh."));
  append(tables_, std::move(generators));

  auto models = materials::material_tables();
  tables_.push_back(selector_section("body.material", "model", models, "The body's constitutive model."));
  std::vector<ParamTable> model_sections;  // each model's own sub-tables of [[body]]
  for (auto& model : models) append(model_sections, std::move(model.companions));
  for (auto& model : models) model.companions.clear();
  append(tables_, std::move(models));
  append(tables_, std::move(model_sections));

  append(tables_, tables::body_details());

  auto terms = rkpm::terms::term_tables();
  tables_.push_back(selector_section("term", "type", terms,
                                     "A physics term. Only the terms a scene declares are built."));
  append(tables_, std::move(terms));

  for (std::size_t i = 0; i < tables_.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (tables_[i].id() == tables_[j].id()) throw std::logic_error("parameter table declared twice: " + tables_[i].id());
    }
  }
}

const ParamRegistry& ParamRegistry::instance() {
  static const ParamRegistry registry;
  return registry;
}

const ParamTable* ParamRegistry::section(std::string_view section) const {
  for (const auto& t : tables_) {
    if (t.section == section && t.selector_value.empty()) return &t;
  }
  return nullptr;
}

const ParamTable* ParamRegistry::variant(std::string_view section, std::string_view value) const {
  for (const auto& t : tables_) {
    if (t.section == section && !t.selector_value.empty() && t.selector_value == value) return &t;
  }
  return nullptr;
}

std::vector<std::string> ParamRegistry::variant_names(std::string_view section) const {
  std::vector<std::string> out;
  for (const auto& t : tables_) {
    if (t.section == section && !t.selector_value.empty()) out.push_back(t.selector_value);
  }
  return out;
}

}  // namespace rkpm::scene
