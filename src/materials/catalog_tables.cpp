// The scene side of the material catalog: every model's [body.material] table
// (compiled into rkpm_scene).
#include "materials/catalog.hpp"

namespace rkpm::materials {

scene::ParamTable material_table(std::string model, std::string help, bool director) {
  scene::ParamTable t;
  t.section = "body.material";
  t.selector_key = "model";
  t.selector_value = std::move(model);
  t.help = std::move(help);
  if (director) t.companion_sections = {"body.director"};
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
