// One function per physics term, each returning the term's parameter table.
// To add a term: write terms/<name>.cpp declaring its table, declare the function
// here and list it in term_list.cpp.
#pragma once

#include "rkpm/scene/param_spec.hpp"

namespace rkpm::scene::terms {

// A [[term]] variant table with its selector set.
ParamTable term_table(std::string type, std::string help);

ParamTable body_force();
ParamTable surface_pressure();
ParamTable volume_constraint();
ParamTable surface_tension();
ParamTable contact();
ParamTable wall_contact();

}  // namespace rkpm::scene::terms
