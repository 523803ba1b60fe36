#include "rkpm/sim/state_record.hpp"

#include <fmt/format.h>

#include <cstring>

namespace rkpm::sim {

namespace {

const char* type_name(StateRecord::Type t) {
  switch (t) {
    case StateRecord::Type::Real: return "real";
    case StateRecord::Type::Integer: return "integer";
    case StateRecord::Type::Text: return "text";
  }
  return "unknown";
}

template <class T>
StateRecord::Field make_field(StateRecord::Type type, std::uint32_t components, std::uint64_t count, const T* data) {
  StateRecord::Field f;
  f.type = type;
  f.components = components;
  f.count = count;
  f.bytes.assign(reinterpret_cast<const char*>(data), count * components * sizeof(T));
  return f;
}

}  // namespace

void StateRecord::put_field(const std::string& name, Field field) { fields_[name] = std::move(field); }

void StateRecord::put_real(const std::string& name, double value) {
  put_field(name, make_field(Type::Real, 1, 1, &value));
}

void StateRecord::put_integer(const std::string& name, std::int64_t value) {
  put_field(name, make_field(Type::Integer, 1, 1, &value));
}

void StateRecord::put_reals(const std::string& name, const std::vector<double>& values) {
  put_field(name, make_field(Type::Real, 1, values.size(), values.data()));
}

void StateRecord::put_vectors(const std::string& name, const std::vector<Vec3>& values) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 is three packed doubles");
  put_field(name, make_field(Type::Real, 3, values.size(), reinterpret_cast<const double*>(values.data())));
}

void StateRecord::put_text(const std::string& name, const std::string& text) {
  put_field(name, make_field(Type::Text, 1, text.size(), text.data()));
}

const StateRecord::Field& StateRecord::find(const std::string& name, Type type, std::uint32_t components) const {
  const auto it = fields_.find(name);
  if (it == fields_.end()) throw StateError(fmt::format("field '{}' is missing", name));
  const Field& f = it->second;
  if (f.type != type || f.components != components)
    throw StateError(fmt::format("field '{}' holds {} x {} values, expected {} x {}", name, type_name(f.type),
                                 f.components, type_name(type), components));
  return f;
}

double StateRecord::real(const std::string& name) const {
  const Field& f = find(name, Type::Real, 1);
  if (f.count != 1) throw StateError(fmt::format("field '{}' has {} values, expected 1", name, f.count));
  double v;
  std::memcpy(&v, f.bytes.data(), sizeof v);
  return v;
}

std::int64_t StateRecord::integer(const std::string& name) const {
  const Field& f = find(name, Type::Integer, 1);
  if (f.count != 1) throw StateError(fmt::format("field '{}' has {} values, expected 1", name, f.count));
  std::int64_t v;
  std::memcpy(&v, f.bytes.data(), sizeof v);
  return v;
}

std::vector<double> StateRecord::reals(const std::string& name) const {
  const Field& f = find(name, Type::Real, 1);
  std::vector<double> v(f.count);
  if (!v.empty()) std::memcpy(v.data(), f.bytes.data(), f.bytes.size());
  return v;
}

std::vector<double> StateRecord::reals(const std::string& name, std::size_t expected) const {
  const Field& f = find(name, Type::Real, 1);
  if (f.count != expected)
    throw StateError(fmt::format("field '{}' has {} values, expected {}", name, f.count, expected));
  return reals(name);
}

std::vector<Vec3> StateRecord::vectors(const std::string& name, std::size_t expected) const {
  const Field& f = find(name, Type::Real, 3);
  if (f.count != expected)
    throw StateError(fmt::format("field '{}' has {} vectors, expected {}", name, f.count, expected));
  std::vector<Vec3> v(f.count);
  if (!v.empty()) std::memcpy(static_cast<void*>(v.data()), f.bytes.data(), f.bytes.size());
  return v;
}

std::string StateRecord::text(const std::string& name) const { return find(name, Type::Text, 1).bytes; }

void StateRecord::put_record(const std::string& prefix, const StateRecord& other) {
  for (const auto& [name, field] : other.fields_) fields_[prefix + name] = field;
}

StateRecord StateRecord::record(const std::string& prefix) const {
  StateRecord r;
  for (auto it = fields_.lower_bound(prefix); it != fields_.end() && it->first.compare(0, prefix.size(), prefix) == 0;
       ++it)
    r.fields_[it->first.substr(prefix.size())] = it->second;
  return r;
}

}  // namespace rkpm::sim
