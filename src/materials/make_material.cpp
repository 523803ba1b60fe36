// The simulation side of the material catalog: a validated [body.material] table
// becomes the body's material.
#include "materials/catalog.hpp"

#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/body.hpp"
#include "rkpm/sim/build.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace rkpm::materials {

std::string make_material(const scene::BodySpec& spec, sim::Body& body) {
  const scene::ParamSet& p = spec.material;
  const std::string& model = spec.model();
  bool built = false;
  std::string note;
  try {
#define RKPM_MATERIAL(entry)    \
  if (!built && model == #entry) { \
    note = entry::build(spec, body); \
    built = true;               \
  }
#include "materials/catalog.def"
#undef RKPM_MATERIAL
  } catch (const std::invalid_argument& e) {
    throw sim::SetupError(
        fmt::format("{}:{}: [{}] body '{}': {}", p.file(), p.table_line(), p.section(), body.name, e.what()));
  }
  // Unreachable for a validated scene: the registry's model choices are the catalog's.
  if (!built)
    throw sim::SetupError(fmt::format("{}:{}: [{}] model = \"{}\": not in the material catalog", p.file(),
                                      p.table_line(), p.section(), model));
  return note;
}

}  // namespace rkpm::materials
