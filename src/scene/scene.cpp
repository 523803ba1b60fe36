#include "rkpm/scene/scene.hpp"

#include "rkpm/scene/param_registry.hpp"

#include <stdexcept>

namespace rkpm::scene {

const std::vector<std::string>& BodySpec::surfaces() const {
  if (!file_surfaces.empty()) return file_surfaces;
  return ParamRegistry::instance().variant("body.cloud", generator())->surfaces;
}

const ParamSet& BodySpec::material_section(const std::string& name) const {
  const auto it = material_sections.find(name);
  if (it == material_sections.end())
    throw std::logic_error("model \"" + model() + "\" declares no [body." + name + "] table");
  return it->second;
}

const BodySpec* Scene::find_body(std::string_view name) const {
  for (const auto& b : bodies) {
    if (b.name() == name) return &b;
  }
  return nullptr;
}

std::vector<const TermSpec*> Scene::terms_of(std::string_view type) const {
  std::vector<const TermSpec*> out;
  for (const auto& t : terms) {
    if (t.type() == type) out.push_back(&t);
  }
  return out;
}

}  // namespace rkpm::scene
