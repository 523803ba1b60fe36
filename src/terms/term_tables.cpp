// The scene side of the catalog: every term's parameter table (compiled into rkpm_scene).
#include "terms/catalog.hpp"

namespace rkpm::terms {

scene::ParamTable term_table(std::string type, std::string help) {
  scene::ParamTable t;
  t.section = "term";
  t.selector_key = "type";
  t.selector_value = std::move(type);
  t.help = std::move(help);
  return t;
}

std::vector<scene::ParamTable> term_tables() {
  return {
#define RKPM_TERM(kind) kind::table(),
#include "terms/catalog.def"
#undef RKPM_TERM
  };
}

}  // namespace rkpm::terms
