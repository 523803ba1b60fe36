// A parameter table bound to a plain settings struct: each key is spelled once,
// where it is declared, next to the member it fills.
//
//   const SettingsTable<Settings> table = SettingsTable<Settings>(term_table("contact", "..."))
//       .bind(&Settings::epsilon, ParamSpec::real("epsilon", "J").greater_than(0).mark_required())
//       .bind(&Settings::law, ParamSpec::choice("stiffness_law", {"none", "linear"}),
//             [](const std::string& v) { return v == "linear" ? Law::linear : Law::none; });
//   Settings s = table.read(params);   // params: the validated ParamSet of that table
//
// The scene registry takes `table()` for validation and the reference; the code that
// builds a term or a material reads its Settings through `read` and never names a key.
// A key that is absent (optional, without a default) leaves the member's initial value.
#pragma once

#include "rkpm/scene/param_set.hpp"
#include "rkpm/scene/param_spec.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace rkpm::scene {

// The value of `key` in `p` as the declared type T (the plain types of ParamValue,
// and std::array<double, N> for a real_list of fixed length N).
template <class T>
T param_value(const ParamSet& p, const std::string& key) {
  if constexpr (std::is_same_v<T, double>) return p.real(key);
  else if constexpr (std::is_same_v<T, std::int64_t>) return p.integer(key);
  else if constexpr (std::is_same_v<T, bool>) return p.flag(key);
  else if constexpr (std::is_same_v<T, std::string>) return p.text(key);
  else if constexpr (std::is_same_v<T, Vec3>) return p.vec3(key);
  else if constexpr (std::is_same_v<T, Int3>) return p.int3(key);
  else if constexpr (std::is_same_v<T, std::vector<std::string>>) return p.texts(key);
  else if constexpr (std::is_same_v<T, std::vector<double>>) return p.reals(key);
  else {
    static_assert(std::is_same_v<T, std::array<double, std::tuple_size_v<T>>>, "no ParamSet getter for this type");
    const auto& v = p.reals(key);
    T out{};
    for (std::size_t i = 0; i < out.size() && i < v.size(); ++i) out[i] = v[i];
    return out;
  }
}

template <class Settings>
class SettingsTable {
 public:
  explicit SettingsTable(ParamTable table) : table_(std::move(table)) {}

  // Declares `spec` and reads its value into `member` unchanged.
  template <class T>
  SettingsTable& bind(T Settings::*member, ParamSpec spec) {
    return bind_with<T>(member, std::move(spec), [](T value) { return value; });
  }

  // Declares `spec` and reads its value (of the spec's own type) through `convert`.
  template <class T, class Convert>
  SettingsTable& bind(T Settings::*member, ParamSpec spec, Convert convert) {
    using Raw = std::decay_t<typename first_argument<decltype(&Convert::operator())>::type>;
    return bind_with<Raw>(member, std::move(spec), std::move(convert));
  }

  // Checks between keys and derived defaults (ParamTable::finish).
  SettingsTable& finish(std::function<void(ParamSet&)> check) {
    table_.finish = std::move(check);
    return *this;
  }

  const ParamTable& table() const { return table_; }

  Settings read(const ParamSet& p) const {
    Settings s{};
    for (const auto& r : readers_) r(p, s);
    return s;
  }

 private:
  template <class M>
  struct first_argument;
  template <class R, class C, class A>
  struct first_argument<R (C::*)(A) const> {
    using type = A;
  };

  template <class Raw, class T, class Convert>
  SettingsTable& bind_with(T Settings::*member, ParamSpec spec, Convert convert) {
    const std::string key = spec.name;
    table_.specs.push_back(std::move(spec));
    readers_.push_back([key, member, convert](const ParamSet& p, Settings& s) {
      if (p.has(key)) s.*member = convert(param_value<Raw>(p, key));
    });
    return *this;
  }

  ParamTable table_;
  std::vector<std::function<void(const ParamSet&, Settings&)>> readers_;
};

}  // namespace rkpm::scene
