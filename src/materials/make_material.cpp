// The simulation side of the material catalog: a validated [body.material] table
// becomes the body's material.
#include "materials/catalog.hpp"

#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/body.hpp"
#include "rkpm/sim/build.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <type_traits>
#include <variant>

namespace rkpm::materials {

void make_material(const scene::BodySpec& spec, sim::Body& body) {
  const scene::ParamSet& p = spec.material;
  const std::string& model = spec.model();
  bool built = false;
  try {
#define RKPM_MATERIAL(entry)    \
  if (!built && model == #entry) { \
    entry::build(spec, body);   \
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
  // The scene gives a body a [body.director] table exactly when its model's table says
  // so; the model's body material must agree, or the force pass would miss the field.
  const bool needs_director =
      std::visit([](const auto& m) { return std::decay_t<decltype(m)>::needs_director; }, body.material);
  if (needs_director != body.director.has_value())
    throw std::logic_error(fmt::format("material model \"{}\": its table and its body material disagree on "
                                       "the director field",
                                       model));
}

}  // namespace rkpm::materials
