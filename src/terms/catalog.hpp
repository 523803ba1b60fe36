// The physics terms a scene can declare, taken from catalog.def: the scene registry
// validates [[term]] tables against `term_tables()`, and build_world creates the
// declared terms through `make_term`. Nothing else compares a term's type string.
#pragma once

#include "rkpm/scene/param_set.hpp"
#include "rkpm/scene/param_spec.hpp"

#include <memory>
#include <vector>

namespace rkpm::scene {
struct TermSpec;
}
namespace rkpm::sim {
class Term;
struct World;
}  // namespace rkpm::sim

namespace rkpm::terms {

#define RKPM_TERM(kind)                                                                 \
  namespace kind {                                                                      \
  scene::ParamTable table();                                                            \
  std::unique_ptr<sim::Term> build(const scene::ParamSet& params, sim::World& world);   \
  }
#include "terms/catalog.def"
#undef RKPM_TERM

// The [[term]] variant tables, in catalog order (rkpm_scene: the registry's source).
std::vector<scene::ParamTable> term_tables();

// Creates the term a validated [[term]] table declares (rkpm_sim). Throws
// sim::SetupError, naming the file and line, when the scene cannot be built.
std::unique_ptr<sim::Term> make_term(const scene::TermSpec& spec, sim::World& world);

// A [[term]] variant table with its selector set: the start of every term's table.
scene::ParamTable term_table(std::string type, std::string help);

}  // namespace rkpm::terms
