// A JSON value for run summaries (summary.json), serialised by nlohmann/json (a
// private dependency: json.cpp). Objects keep insertion order so the file reads in the
// order the program filled it. Only writing is supported; nothing in the simulator
// needs to read JSON.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace rkpm::io {

class Json {
 public:
  using Array = std::vector<Json>;
  using Object = std::vector<std::pair<std::string, Json>>;
  using Value = std::variant<std::nullptr_t, bool, std::int64_t, double, std::string, Array, Object>;

  Json() = default;  // null
  Json(std::nullptr_t) {}
  Json(bool b) : value_(b) {}
  template <typename T, std::enable_if_t<std::is_integral_v<T> && !std::is_same_v<T, bool>, int> = 0>
  Json(T i) : value_(checked_int64(i)) {}
  template <typename T, std::enable_if_t<std::is_floating_point_v<T>, int> = 0>
  Json(T x) : value_(static_cast<double>(x)) {}
  Json(const char* s) : value_(std::string(s)) {}
  Json(std::string s) : value_(std::move(s)) {}
  Json(Array a) : value_(std::move(a)) {}
  Json(Object o) : value_(std::move(o)) {}

  static Json object() { return Json(Object{}); }
  static Json array() { return Json(Array{}); }

  // Object: sets `key` (replacing an existing value). Throws if not an object.
  Json& set(const std::string& key, Json value);
  // Array: appends. Throws if not an array.
  Json& push_back(Json value);

  // Serialises with `indent` spaces per level (0: one line). Numbers are
  // printed as the shortest text that reads back to the same double. Throws
  // std::invalid_argument naming the key path (e.g. `metrics.energy`) if a
  // number is NaN or infinite: JSON has no spelling for them and a summary
  // must never claim a non-finite result silently.
  std::string dump(int indent = 2) const;

  const Value& value() const { return value_; }

 private:
  template <typename T>
  static std::int64_t checked_int64(T i) {
    if constexpr (std::is_unsigned_v<T> && sizeof(T) >= sizeof(std::int64_t)) {
      if (i > static_cast<T>(INT64_MAX)) throw_int_overflow();
    }
    return static_cast<std::int64_t>(i);
  }
  [[noreturn]] static void throw_int_overflow();

  Value value_{nullptr};
};

// JSON string literal for `s` (quotes included), escaping '"', '\\' and
// control characters; other bytes (UTF-8) pass through unchanged.
std::string json_quote(const std::string& s);

// dump() followed by an atomic replace of `path` (temporary + rename).
void write_json_atomically(const std::filesystem::path& path, const Json& value, int indent = 2);

}  // namespace rkpm::io
