#include "rkpm/scene/param_spec.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <utility>

namespace rkpm::scene {

std::string type_name(ParamType type) {
  switch (type) {
    case ParamType::real: return "real";
    case ParamType::integer: return "integer";
    case ParamType::boolean: return "boolean";
    case ParamType::text: return "string";
    case ParamType::choice: return "choice";
    case ParamType::vec3: return "vec3";
    case ParamType::int3: return "int3";
    case ParamType::text_list: return "string list";
    case ParamType::real_list: return "real list";
  }
  return "?";
}

namespace {

std::string quoted(const std::string& s) { return fmt::format("\"{}\"", s); }

template <class Range, class Format>
std::string bracketed(const Range& items, Format format) {
  std::string out = "[";
  bool first = true;
  for (const auto& item : items) {
    if (!first) out += ", ";
    out += format(item);
    first = false;
  }
  return out + "]";
}

std::string number(double v) { return fmt::format("{}", v); }

}  // namespace

std::string format_value(const ParamValue& value) {
  struct Formatter {
    std::string operator()(double v) const { return number(v); }
    std::string operator()(std::int64_t v) const { return fmt::format("{}", v); }
    std::string operator()(bool v) const { return v ? "true" : "false"; }
    std::string operator()(const std::string& v) const { return quoted(v); }
    std::string operator()(const Vec3& v) const {
      return fmt::format("[{}, {}, {}]", number(v.x()), number(v.y()), number(v.z()));
    }
    std::string operator()(const Int3& v) const { return fmt::format("[{}, {}, {}]", v[0], v[1], v[2]); }
    std::string operator()(const std::vector<std::string>& v) const { return bracketed(v, quoted); }
    std::string operator()(const std::vector<double>& v) const { return bracketed(v, number); }
  };
  return std::visit(Formatter{}, value);
}

// --- declaration builders -------------------------------------------------------

namespace {
ParamSpec make(std::string name, ParamType type, std::string unit) {
  ParamSpec spec;
  spec.name = std::move(name);
  spec.type = type;
  spec.unit = std::move(unit);
  return spec;
}
}  // namespace

ParamSpec ParamSpec::real(std::string name, std::string unit) { return make(std::move(name), ParamType::real, std::move(unit)); }
ParamSpec ParamSpec::integer(std::string name) { return make(std::move(name), ParamType::integer, "-"); }
ParamSpec ParamSpec::boolean(std::string name) { return make(std::move(name), ParamType::boolean, "-"); }
ParamSpec ParamSpec::text(std::string name) { return make(std::move(name), ParamType::text, "-"); }
ParamSpec ParamSpec::choice(std::string name, std::vector<std::string> choices) {
  ParamSpec spec = make(std::move(name), ParamType::choice, "-");
  spec.choices = std::move(choices);
  return spec;
}
ParamSpec ParamSpec::vec3(std::string name, std::string unit) { return make(std::move(name), ParamType::vec3, std::move(unit)); }
ParamSpec ParamSpec::int3(std::string name) { return make(std::move(name), ParamType::int3, "-"); }
ParamSpec ParamSpec::text_list(std::string name) { return make(std::move(name), ParamType::text_list, "-"); }
ParamSpec ParamSpec::real_list(std::string name, std::string unit) { return make(std::move(name), ParamType::real_list, std::move(unit)); }

ParamSpec& ParamSpec::defaults(ParamValue value) {
  // A real default written as an integer literal (`defaults(0)`) is still a real.
  if (type == ParamType::real || type == ParamType::real_list) {
    if (const auto* i = std::get_if<std::int64_t>(&value)) value = static_cast<double>(*i);
  }
  default_value = std::move(value);
  return *this;
}
ParamSpec& ParamSpec::mark_required() { required = true; return *this; }
ParamSpec& ParamSpec::absent_means(std::string note) { default_note = std::move(note); return *this; }
ParamSpec& ParamSpec::greater_than(double v) { min = Bound{v, false}; return *this; }
ParamSpec& ParamSpec::at_least(double v) { min = Bound{v, true}; return *this; }
ParamSpec& ParamSpec::less_than(double v) { max = Bound{v, false}; return *this; }
ParamSpec& ParamSpec::at_most(double v) { max = Bound{v, true}; return *this; }
ParamSpec& ParamSpec::with_length(std::size_t n) { length = n; return *this; }
ParamSpec& ParamSpec::refers_to(Reference r) { reference = r; return *this; }
ParamSpec& ParamSpec::help(std::string text) { help_text = std::move(text); return *this; }

bool ParamSpec::in_range(double v) const {
  if (min && (min->inclusive ? v < min->value : v <= min->value)) return false;
  if (max && (max->inclusive ? v > max->value : v >= max->value)) return false;
  return true;
}

std::string ParamSpec::range_text() const {
  if (type == ParamType::choice) {
    std::string out;
    for (const auto& c : choices) out += (out.empty() ? "" : " | ") + c;
    return out;
  }
  if (min && max) {
    return fmt::format("in {}{}, {}{}", min->inclusive ? "[" : "(", number(min->value),
                       number(max->value), max->inclusive ? "]" : ")");
  }
  if (min) return fmt::format("{} {}", min->inclusive ? ">=" : ">", number(min->value));
  if (max) return fmt::format("{} {}", max->inclusive ? "<=" : "<", number(max->value));
  switch (reference) {
    case Reference::body: return "a body name";
    case Reference::bodies: return "body names";
    case Reference::surface: return "a surface name";
    case Reference::none: break;
  }
  const bool numeric = type == ParamType::real || type == ParamType::integer || type == ParamType::vec3 ||
                       type == ParamType::int3 || type == ParamType::real_list;
  return numeric ? "any" : "-";
}

std::string ParamSpec::default_text() const {
  if (required) return "required";
  if (default_value) return format_value(*default_value);
  return default_note.empty() ? "none" : default_note;
}

std::string ParamSpec::expectation() const {
  const bool has_range = min || max;
  const std::string unit_text = unit == "-" ? "" : fmt::format(" [{}]", unit);
  switch (type) {
    case ParamType::real:
    case ParamType::integer:
      return fmt::format("a{} {}{}{}", type == ParamType::integer ? "n" : "", type_name(type),
                         has_range ? " " + range_text() : "", unit_text);
    case ParamType::boolean: return "true or false";
    case ParamType::text: return "a string";
    case ParamType::choice: {
      std::string out = "one of ";
      for (std::size_t i = 0; i < choices.size(); ++i) out += (i ? ", " : "") + quoted(choices[i]);
      return out;
    }
    case ParamType::vec3:
    case ParamType::int3:
      return fmt::format("an array of 3 {}s{}{}", type == ParamType::vec3 ? "real" : "integer",
                         has_range ? ", each " + range_text() : "", unit_text);
    case ParamType::text_list:
      return length ? fmt::format("an array of {} strings", length) : "an array of strings";
    case ParamType::real_list:
      return fmt::format("an array of {}reals{}{}", length ? fmt::format("{} ", length) : "",
                         has_range ? ", each " + range_text() : "", unit_text);
  }
  return "?";
}

// --- tables ---------------------------------------------------------------------

std::string ParamTable::id() const {
  return selector_value.empty() ? section : fmt::format("{} {}={}", section, selector_key, selector_value);
}

std::string ParamTable::heading() const {
  const bool array = section == "term" || section == "body" || section == "body.boundary";
  std::string out = array ? fmt::format("[[{}]]", section) : fmt::format("[{}]", section);
  if (!selector_value.empty()) out += fmt::format(" {} = \"{}\"", selector_key, selector_value);
  return out;
}

const ParamSpec* ParamTable::find(std::string_view name) const {
  for (const auto& spec : specs) {
    if (spec.name == name) return &spec;
  }
  return nullptr;
}

std::vector<std::string> ParamTable::names() const {
  std::vector<std::string> out;
  for (const auto& spec : specs) out.push_back(spec.name);
  return out;
}

}  // namespace rkpm::scene
