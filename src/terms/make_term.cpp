// The simulation side of the catalog: a declared [[term]] becomes its Term.
#include "terms/catalog.hpp"

#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/build.hpp"
#include "rkpm/sim/world.hpp"

#include <fmt/format.h>

namespace rkpm::terms {

std::unique_ptr<sim::Term> make_term(const scene::TermSpec& spec, sim::World& world) {
  const std::string& type = spec.type();
#define RKPM_TERM(kind) \
  if (type == #kind) return kind::build(spec.params, world);
#include "terms/catalog.def"
#undef RKPM_TERM
  // Unreachable for a validated scene: the registry's type choices are the catalog's.
  throw sim::SetupError(fmt::format("{}:{}: [term] type = \"{}\": not in the term catalog", spec.params.file(),
                                    spec.params.table_line(), type));
}

}  // namespace rkpm::terms
