// The scene side of the material catalog: every model's [body.material] table
// (compiled into rkpm_scene).
#include "materials/catalog.hpp"

namespace rkpm::materials {

scene::ParamTable material_table(std::string model, std::string help, std::vector<scene::ParamTable> own_sections) {
  scene::ParamTable t;
  t.section = "body.material";
  t.selector_key = "model";
  t.selector_value = std::move(model);
  t.help = std::move(help);
  for (auto& section : own_sections) {
    t.companion_sections.push_back(section.section);
    t.companions.push_back(std::move(section));
  }
  return t;
}

std::vector<scene::ParamTable> material_tables() {
  return {
#define RKPM_MATERIAL(model) model::table(),
#include "materials/catalog.def"
#undef RKPM_MATERIAL
  };
}

}  // namespace rkpm::materials
