// The constitutive models a scene can select, taken from catalog.def: the scene
// registry validates [body.material] tables against `material_tables()`, and
// build_world gives a body its material through `make_material`. Nothing outside a
// model's folder compares its model string.
#pragma once

#include "rkpm/scene/param_spec.hpp"

#include <string>
#include <vector>

namespace rkpm::scene {
struct BodySpec;
}
namespace rkpm::sim {
struct Body;
}

namespace rkpm::materials {

// Each model's entry points. `build` sets body.material, its per-point state included,
// from the validated [body.material] table (and the model's own sub-tables); the cloud, the RK operators and the initial state exist when
// it is called. It returns a note for the run log, or nothing, and throws
// std::invalid_argument naming the parameter.
#define RKPM_MATERIAL(model)                                       \
  namespace model {                                                \
  scene::ParamTable table();                                       \
  std::string build(const scene::BodySpec& spec, sim::Body& body); \
  }
#include "materials/catalog.def"
#undef RKPM_MATERIAL

// The [body.material] variant tables, in catalog order (rkpm_scene: the registry's source).
std::vector<scene::ParamTable> material_tables();

// A [body.material] variant table with its selector set: the start of every model's table.
// `own_sections`: the model's own sub-tables of [[body]] (the LCE's own table),
// which only its bodies take; BodySpec::material_section reads them.
scene::ParamTable material_table(std::string model, std::string help, std::vector<scene::ParamTable> own_sections = {});

// Gives the body the material its validated [body.material] table declares (rkpm_sim),
// and returns the model's note for the run log (empty: none). Throws sim::SetupError
// naming the file, line and body when the parameters are invalid.
std::string make_material(const scene::BodySpec& spec, sim::Body& body);

}  // namespace rkpm::materials
