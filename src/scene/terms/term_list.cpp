// The registered physics terms, in the order the reference lists them.
#include "tables/tables.hpp"
#include "terms/terms.hpp"

namespace rkpm::scene {

ParamTable terms::term_table(std::string type, std::string help) {
  ParamTable t;
  t.section = "term";
  t.selector_key = "type";
  t.selector_value = std::move(type);
  t.help = std::move(help);
  return t;
}

std::vector<ParamTable> tables::terms() {
  return {terms::body_force(), terms::surface_pressure(), terms::volume_constraint(),
          terms::surface_tension(), terms::contact(), terms::wall_contact()};
}

}  // namespace rkpm::scene
