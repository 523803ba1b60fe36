// The one place that knows every parameter table: the run sections, the body
// sub-tables, the cloud generators, the materials and the physics terms. A new
// term declares its table in its own folder and is listed once in the term catalog
// (src/terms/catalog.def); validation, the `rkpm params` reference and the choice
// lists ("generator", "model", "type") then follow automatically.
#pragma once

#include "rkpm/scene/param_spec.hpp"

#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace rkpm::scene {

class ParamRegistry {
 public:
  // Built once, on first use; immutable afterwards (safe to share between threads).
  static const ParamRegistry& instance();

  // All tables in reference order: each section followed by its variants.
  const std::vector<ParamTable>& tables() const { return tables_; }

  // The section's own table ("integrator", "body.cloud", "term"); nullptr if unknown.
  const ParamTable* section(std::string_view section) const;
  // A variant of a section ("body.cloud", "shell"); nullptr if unknown.
  const ParamTable* variant(std::string_view section, std::string_view value) const;
  // Names of the section's variants in declaration order ("block", "sphere", ...).
  std::vector<std::string> variant_names(std::string_view section) const;

 private:
  ParamRegistry();
  std::vector<ParamTable> tables_;
};

enum class ParamFormat { text, markdown };

// The whole parameter reference: every table, every key with its type, unit,
// default, valid range and help. `rkpm params` prints the text form; the README's
// parameter reference is the markdown form.
void print_params(std::ostream& out, ParamFormat format);

}  // namespace rkpm::scene
