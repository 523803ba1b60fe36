// The parameter tables, grouped by the file that declares them. Only the registry
// (param_registry.cpp) calls these; everything else asks the registry.
#pragma once

#include "rkpm/scene/param_spec.hpp"

#include <vector>

namespace rkpm::scene::tables {

std::vector<ParamTable> run_sections();     // [scene], [integrator], [output]
ParamTable body();                          // [[body]]
std::vector<ParamTable> body_details();     // [body.rk], [body.initial], [[body.boundary]]
// The variants of [body.material] and [body.cloud] come from the material and cloud
// catalogs (src/materials/catalog.hpp, src/clouds/catalog.hpp).

}  // namespace rkpm::scene::tables
