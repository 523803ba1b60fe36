// The parameter tables, grouped by the file that declares them. Only the registry
// (param_registry.cpp) calls these; everything else asks the registry.
#pragma once

#include "rkpm/scene/param_spec.hpp"

#include <vector>

namespace rkpm::scene::tables {

std::vector<ParamTable> run_sections();     // [scene], [integrator], [output]
ParamTable body();                          // [[body]]
std::vector<ParamTable> body_details();     // [body.director], [body.rk], [body.initial], [[body.boundary]]
std::vector<ParamTable> cloud_generators(); // variants of [body.cloud], selected by `generator`
std::vector<ParamTable> materials();        // variants of [body.material], selected by `model`

}  // namespace rkpm::scene::tables
