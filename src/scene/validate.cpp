#include "validate.hpp"

#include "rkpm/scene/param_registry.hpp"
#include "spelling.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

namespace rkpm::scene {

int line_of(const toml::node& node) { return static_cast<int>(node.source().begin.line); }

std::string toml_text(const toml::node& node) {
  if (const auto* s = node.as_string()) return fmt::format("\"{}\"", s->get());
  if (const auto* i = node.as_integer()) return fmt::format("{}", i->get());
  if (const auto* d = node.as_floating_point()) return fmt::format("{}", d->get());
  if (const auto* b = node.as_boolean()) return b->get() ? "true" : "false";
  if (const auto* a = node.as_array()) {
    std::string out = "[";
    for (std::size_t k = 0; k < a->size(); ++k) out += (k ? ", " : "") + toml_text(*a->get(k));
    return out + "]";
  }
  if (node.is_table()) return "{...}";
  std::ostringstream os;  // dates and times
  node.visit([&](const auto& v) { os << v; });
  return os.str();
}

namespace {

// Reads one value; returns nullopt when the TOML type does not fit the declared one
// (the caller reports it with the declaration's expectation).
class Converter {
 public:
  explicit Converter(const ParamSpec& spec) : spec_(spec) {}

  std::optional<ParamValue> operator()(const toml::node& node) const {
    switch (spec_.type) {
      case ParamType::real: return number(node);
      case ParamType::integer: return whole(node);
      case ParamType::boolean:
        if (const auto* b = node.as_boolean()) return ParamValue(b->get());
        return std::nullopt;
      case ParamType::text:
      case ParamType::choice:
        if (const auto* s = node.as_string()) return ParamValue(s->get());
        return std::nullopt;
      case ParamType::vec3: {
        const auto items = array_of(node, 3, [&](const toml::node& n) { return number(n); });
        if (!items) return std::nullopt;
        return ParamValue(Vec3((*items)[0], (*items)[1], (*items)[2]));
      }
      case ParamType::int3: {
        const auto items = array_of(node, 3, [&](const toml::node& n) { return whole(n); });
        if (!items) return std::nullopt;
        return ParamValue(Int3{(*items)[0], (*items)[1], (*items)[2]});
      }
      case ParamType::text_list: {
        const auto items = array_of(node, spec_.length, [](const toml::node& n) -> std::optional<std::string> {
          if (const auto* s = n.as_string()) return s->get();
          return std::nullopt;
        });
        if (!items) return std::nullopt;
        return ParamValue(*items);
      }
      case ParamType::real_list: {
        const auto items = array_of(node, spec_.length, [&](const toml::node& n) { return number(n); });
        if (!items) return std::nullopt;
        return ParamValue(*items);
      }
    }
    return std::nullopt;
  }

 private:
  // Integers are accepted where reals are expected; non-finite reals and values
  // outside the declared range are refused.
  std::optional<double> number(const toml::node& node) const {
    double v = 0.0;
    if (const auto* d = node.as_floating_point()) {
      v = d->get();
    } else if (const auto* i = node.as_integer()) {
      v = static_cast<double>(i->get());
    } else {
      return std::nullopt;
    }
    if (!std::isfinite(v) || !spec_.in_range(v)) return std::nullopt;
    return v;
  }

  std::optional<std::int64_t> whole(const toml::node& node) const {
    const auto* i = node.as_integer();
    if (!i || !spec_.in_range(static_cast<double>(i->get()))) return std::nullopt;
    // int3 values are counts handed to generators as int.
    if (spec_.type == ParamType::int3 && std::abs(i->get()) > std::numeric_limits<int>::max()) return std::nullopt;
    return i->get();
  }

  template <class Read>
  static auto array_of(const toml::node& node, std::size_t length, Read read)
      -> std::optional<std::vector<typename decltype(read(node))::value_type>> {
    const auto* array = node.as_array();
    if (!array || (length != 0 && array->size() != length)) return std::nullopt;
    std::vector<typename decltype(read(node))::value_type> out;
    for (const auto& item : *array) {
      auto v = read(item);
      if (!v) return std::nullopt;
      out.push_back(*v);
    }
    return out;
  }

  const ParamSpec& spec_;
};

// A subnormal double (non-zero, below 2.2e-308 in size) has lost its precision, and
// whatever divides by it overflows (a density of 5e-324 gives zero masses and infinite
// accelerations): such values are refused everywhere, in lists too.
bool holds_subnormal(const toml::node& node) {
  if (const auto* d = node.as_floating_point()) {
    const double v = d->get();
    return v != 0.0 && std::abs(v) < std::numeric_limits<double>::min();
  }
  if (const auto* array = node.as_array()) {
    for (const auto& item : *array)
      if (holds_subnormal(item)) return true;
  }
  return false;
}

const ParamSpec* find_spec(const std::vector<const ParamTable*>& tables, std::string_view name) {
  for (const ParamTable* table : tables) {
    if (const ParamSpec* spec = table->find(name)) return spec;
  }
  return nullptr;
}

std::string expectation_for(const ParamSpec& spec, const toml::node& node) {
  if (spec.type == ParamType::choice) {
    const std::string word = node.as_string() ? node.as_string()->get() : std::string();
    return "one of " + list_with_suggestion(word, spec.choices, true);
  }
  return spec.expectation();
}

}  // namespace

ParamSet validate_table(const toml::table& toml_table, std::vector<const ParamTable*> tables,
                        const TableSite& site, const std::vector<std::string>& skip) {
  ParamSet set(tables, site.file, site.line, site.section);

  for (const auto& [key, node] : toml_table) {
    const std::string name(key.str());
    if (std::find(skip.begin(), skip.end(), name) != skip.end()) continue;
    const ParamSpec* spec = find_spec(tables, name);
    if (!spec) {
      std::vector<std::string> known;
      for (const ParamTable* table : tables) {
        for (auto& n : table->names()) known.push_back(n);
      }
      const std::string scope = tables.back()->selector_value.empty()
                                    ? std::string()
                                    : fmt::format(" for {} = \"{}\"", tables.back()->selector_key,
                                                  tables.back()->selector_value);
      throw SceneError(site.file, line_of(node), site.section, name, toml_text(node),
                       fmt::format("a known key{}: {}", scope, list_with_suggestion(name, known, false)));
    }
    if (holds_subnormal(node)) {
      throw SceneError(site.file, line_of(node), site.section, name, toml_text(node),
                       "0 or a number of at least 2.2e-308 in size (a subnormal number has lost its precision)");
    }
    const auto value = Converter(*spec)(node);
    if (!value) {
      throw SceneError(site.file, line_of(node), site.section, name, toml_text(node),
                       expectation_for(*spec, node));
    }
    if (spec->type == ParamType::choice) {
      const auto& word = std::get<std::string>(*value);
      if (std::find(spec->choices.begin(), spec->choices.end(), word) == spec->choices.end()) {
        throw SceneError(site.file, line_of(node), site.section, name, toml_text(node),
                         expectation_for(*spec, node));
      }
    }
    set.set(name, *value, line_of(node), true);
  }

  for (const ParamTable* table : tables) {
    for (const ParamSpec& spec : table->specs) {
      if (set.has(spec.name)) continue;
      if (spec.required) {
        throw SceneError(site.file, site.line, site.section, spec.name, "",
                         fmt::format("a value for this required key: {}", spec.expectation()));
      }
      if (spec.default_value) set.set(spec.name, *spec.default_value, site.line, false);
    }
  }

  for (const ParamTable* table : tables) {
    if (table->finish) table->finish(set);
  }
  return set;
}

ParamSet validate_variant_table(const toml::table& toml_table, const TableSite& site) {
  const ParamRegistry& registry = ParamRegistry::instance();
  const ParamTable* base = registry.section(site.section);
  const ParamSpec& selector = base->specs.front();  // a variant section's first key selects the variant

  const toml::node* node = toml_table.get(selector.name);
  if (!node) {
    throw SceneError(site.file, site.line, site.section, selector.name, "",
                     fmt::format("a value for this required key: {}", selector.expectation()));
  }
  const auto* word = node->as_string();
  const ParamTable* variant = word ? registry.variant(site.section, word->get()) : nullptr;
  if (!variant) {
    throw SceneError(site.file, line_of(*node), site.section, selector.name, toml_text(*node),
                     expectation_for(selector, *node));
  }
  return validate_table(toml_table, {base, variant}, site);
}

}  // namespace rkpm::scene
