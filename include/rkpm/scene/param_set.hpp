// Validated values of one parameter table, with the line each came from.
//
// Getters are typed and take the declared name. Asking for a name the table does
// not declare, or with the wrong type, is a programming error (std::logic_error),
// never a user error: every user error was reported while validating.
#pragma once

#include "rkpm/scene/param_spec.hpp"
#include "rkpm/scene/scene_error.hpp"

#include <map>
#include <string>
#include <vector>

namespace rkpm::scene {

class ParamSet {
 public:
  ParamSet() = default;
  // `table` must outlive the set (registry tables live for the whole program).
  ParamSet(std::vector<const ParamTable*> tables, std::string file, int line, std::string section);

  double real(const std::string& name) const;
  std::int64_t integer(const std::string& name) const;
  bool flag(const std::string& name) const;
  const std::string& text(const std::string& name) const;    // text or choice
  const std::string& choice(const std::string& name) const;  // choice only
  Vec3 vec3(const std::string& name) const;
  Int3 int3(const std::string& name) const;
  const std::vector<std::string>& texts(const std::string& name) const;
  const std::vector<double>& reals(const std::string& name) const;

  // False only for keys declared without a default that the scene did not give.
  bool has(const std::string& name) const;
  // True when the scene file wrote the key (as opposed to a default).
  bool given(const std::string& name) const;
  // Line of the key in the scene file, or of the table when it was defaulted.
  int line(const std::string& name) const;

  const std::string& file() const { return file_; }
  int table_line() const { return line_; }
  const std::string& section() const { return section_; }
  // The selector value of a variant table ("block", "lce", "contact"), or "".
  std::string variant() const;

  // Used while validating and by ParamTable::finish for derived defaults.
  void set(const std::string& name, ParamValue value, int line, bool given);

  // A SceneError about `name` in this table: `FILE:LINE: [section] name = VALUE: expected ...`.
  SceneError error(const std::string& name, const std::string& expected) const;

 private:
  struct Entry {
    ParamValue value;
    int line = 0;
    bool given = false;
  };
  const ParamSpec& spec(const std::string& name) const;  // throws std::logic_error if undeclared
  const Entry& entry(const std::string& name, ParamType type) const;

  std::vector<const ParamTable*> tables_;  // the section's table and, for variants, the variant
  std::string file_;
  int line_ = 0;
  std::string section_;
  std::map<std::string, Entry> values_;
};

}  // namespace rkpm::scene
