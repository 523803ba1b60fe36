// Validation of one TOML table against its declared parameter tables.
#pragma once

#include "rkpm/scene/param_set.hpp"

#include <toml++/toml.h>

#include <string>
#include <vector>

namespace rkpm::scene {

// Where a table sits in the scene file, for messages.
struct TableSite {
  std::string file;
  std::string section;  // as the user wrote it: "body.cloud", "term"
  int line = 0;         // the table header, or the enclosing table's when it was omitted
};

// The line a TOML node starts on (0 if unknown).
int line_of(const toml::node& node);

// A TOML value as a scene file would spell it, for messages.
std::string toml_text(const toml::node& node);

// Every key of `toml_table` must be declared in one of `tables`; values are
// converted to the declared types and checked against their ranges; missing keys
// take their defaults; required keys must be present; then each table's `finish`
// hook runs. Keys listed in `skip` are sub-tables validated by the caller.
// Throws SceneError.
ParamSet validate_table(const toml::table& toml_table, std::vector<const ParamTable*> tables,
                        const TableSite& site, const std::vector<std::string>& skip = {});

// For sections with variants ([body.cloud] generator, [body.material] model,
// [[term]] type): reads the selector first, then validates the table against the
// section's table plus the selected variant's.
ParamSet validate_variant_table(const toml::table& toml_table, const TableSite& site);

}  // namespace rkpm::scene
