// The parameter tables, grouped by the file that declares them. Only the registry
// (param_registry.cpp) calls these; everything else asks the registry.
#pragma once

#include "rkpm/scene/param_spec.hpp"

#include <vector>

namespace rkpm::scene::tables {

std::vector<ParamTable> run_sections();     // [scene], [integrator], [output]
ParamTable body();                          // [[body]]
std::vector<ParamTable> body_details();     // [body.director], [body.rk], [body.initial], [[body.boundary]]
// The variants of [body.material] come from the material catalog (src/materials/catalog.hpp).
std::vector<ParamTable> cloud_generators(); // variants of [body.cloud], selected by `generator`

}  // namespace rkpm::scene::tables
