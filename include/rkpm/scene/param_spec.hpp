// Declaration of run-time parameters: every key a scene file may contain is
// declared exactly once, with its type, unit, default, valid range and
// help text. Validation, error messages and the `rkpm params` reference are all
// generated from these declarations, so they cannot disagree.
//
// Declaring a parameter reads like a sentence:
//   ParamSpec::real("dt_safety", "-").greater_than(0).at_most(1).defaults(0.5)
//       .help("Fraction of the stable time step actually taken.")
#pragma once

#include "rkpm/common/types.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace rkpm::scene {

enum class ParamType {
  real,         // double; an integer literal is accepted
  integer,      // std::int64_t
  boolean,      // bool
  text,         // free string
  choice,       // one string out of a declared list
  vec3,         // three reals (Vec3)
  int3,         // three integers
  text_list,    // list of strings
  real_list,    // list of reals
};

// Name of the type as printed in messages and the parameter reference.
std::string type_name(ParamType type);

using Int3 = std::array<std::int64_t, 3>;
using ParamValue = std::variant<double, std::int64_t, bool, std::string, Vec3, Int3,
                                std::vector<std::string>, std::vector<double>>;

// The value as a scene file would spell it: 0.5, "cubic", [1, 1, 1], true.
std::string format_value(const ParamValue& value);

// One end of a numeric range. For vec3, int3 and real_list the range applies to
// every component.
struct Bound {
  double value = 0.0;
  bool inclusive = true;
};

// A parameter whose value names another object of the scene. The scene loader
// checks the reference once all bodies are known.
enum class Reference {
  none,
  body,         // text: the name of a declared body
  bodies,       // text_list: names of declared bodies, all different
  surface,      // text: a surface of the body the table belongs to (or names in `body`), or "all"
};

struct ParamSpec {
  std::string name;
  ParamType type = ParamType::real;
  std::string unit = "-";                 // SI unit, "-" for dimensionless
  std::optional<ParamValue> default_value;
  bool required = false;
  std::string default_note;               // when neither required nor defaulted: what absence means
  std::optional<Bound> min, max;
  std::vector<std::string> choices;       // ParamType::choice
  std::size_t length = 0;                 // text_list / real_list: required length, 0 = any
  Reference reference = Reference::none;
  std::string help_text;

  // Start a declaration of the given type.
  static ParamSpec real(std::string name, std::string unit);
  static ParamSpec integer(std::string name);
  static ParamSpec boolean(std::string name);
  static ParamSpec text(std::string name);
  static ParamSpec choice(std::string name, std::vector<std::string> choices);
  static ParamSpec vec3(std::string name, std::string unit);
  static ParamSpec int3(std::string name);
  static ParamSpec text_list(std::string name);
  static ParamSpec real_list(std::string name, std::string unit);

  ParamSpec& defaults(ParamValue value);
  ParamSpec& mark_required();
  ParamSpec& absent_means(std::string note);  // optional key without a fixed default
  ParamSpec& greater_than(double v);
  ParamSpec& at_least(double v);
  ParamSpec& less_than(double v);
  ParamSpec& at_most(double v);
  ParamSpec& with_length(std::size_t n);
  ParamSpec& refers_to(Reference r);
  ParamSpec& help(std::string text);

  // Whether a number satisfies [min, max] with the declared open/closed ends.
  bool in_range(double v) const;
  // "> 0", "in (0, 1]", "any": the range as the reference prints it.
  std::string range_text() const;
  // "required", "0.5", or the absence note.
  std::string default_text() const;
  // What a valid value looks like, for messages: `a real > 0 [Pa]`.
  std::string expectation() const;
};

class ParamSet;

// A table of parameters as it appears in a scene file. Tables with a selector are
// variants of a section: [body.cloud] with generator = "block" accepts the keys of
// the section's own table plus those of the "block" variant.
struct ParamTable {
  std::string section;          // where it appears in a scene: "integrator", "body.cloud", "term"
  std::string selector_key;     // variants only: "generator", "model", "type"
  std::string selector_value;   // variants only: "block", "lce", "contact"
  std::string help;
  std::vector<ParamSpec> specs;
  // Cloud generators: the named surfaces the cloud provides (for boundary
  // conditions and surface terms).
  std::vector<std::string> surfaces;
  // Variants: the sections that exist only alongside this variant (a material model's
  // own sub-tables of [[body]], declared by the model); any other variant rejects them.
  // `companions` holds their tables until the registry takes them in.
  std::vector<std::string> companion_sections;
  std::vector<ParamTable> companions;
  // Consistency checks between keys of this table and derived defaults; throws
  // SceneError through ParamSet::error. May be empty.
  std::function<void(ParamSet&)> finish;

  // "body.cloud" or "body.cloud generator=block": a unique id in the registry.
  std::string id() const;
  // What the reference prints as the heading: [body.cloud] generator = "block".
  std::string heading() const;
  const ParamSpec* find(std::string_view name) const;
  std::vector<std::string> names() const;
};

}  // namespace rkpm::scene
