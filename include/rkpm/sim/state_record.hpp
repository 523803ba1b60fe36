// Named state values, the content of a checkpoint: every value is stored under its
// name with its element type and its shape (components per element, element count),
// so that a reader finds each value by name and reports a missing or mis-sized one
// by name instead of silently reading the wrong numbers. Values are kept as their
// exact bytes (a restart continues bit for bit); names are kept sorted, so the same
// state always gives the same bytes.
#pragma once

#include "rkpm/common/types.hpp"

#include <cstddef>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace rkpm::sim {

// A missing field, a field of another type or size, a malformed record. The message
// names the field.
struct StateError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class StateRecord {
 public:
  enum class Type : std::uint8_t { Real = 1, Integer = 2, Text = 3 };

  struct Field {
    Type type = Type::Real;
    std::uint32_t components = 1;  // values per element (3 for a Vec3)
    std::uint64_t count = 0;       // elements
    std::string bytes;             // count * components values, native byte order
  };

  // Writing: a name is written once (a second write replaces the first).
  void put_real(const std::string& name, double value);
  void put_integer(const std::string& name, std::int64_t value);
  void put_reals(const std::string& name, const std::vector<double>& values);
  void put_vectors(const std::string& name, const std::vector<Vec3>& values);
  void put_text(const std::string& name, const std::string& text);

  // Reading: throws StateError naming the field when it is missing or its type or
  // shape differs from the one asked for.
  double real(const std::string& name) const;
  std::int64_t integer(const std::string& name) const;
  std::vector<double> reals(const std::string& name) const;
  // `expected` elements exactly.
  std::vector<double> reals(const std::string& name, std::size_t expected) const;
  std::vector<Vec3> vectors(const std::string& name, std::size_t expected) const;
  std::string text(const std::string& name) const;

  bool has(const std::string& name) const { return fields_.count(name) != 0; }
  bool empty() const { return fields_.empty(); }
  std::size_t size() const { return fields_.size(); }
  const std::map<std::string, Field>& fields() const { return fields_; }

  // Nesting: every field of `other` under "prefix" + its name, and back.
  void put_record(const std::string& prefix, const StateRecord& other);
  StateRecord record(const std::string& prefix) const;

  // Low level, for the file format: a field as read from a file.
  void put_field(const std::string& name, Field field);

 private:
  const Field& find(const std::string& name, Type type, std::uint32_t components) const;
  std::map<std::string, Field> fields_;
};

}  // namespace rkpm::sim
