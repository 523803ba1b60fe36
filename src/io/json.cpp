#include "rkpm/io/json.hpp"

#include "rkpm/io/atomic_file.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <variant>

namespace rkpm::io {

void Json::throw_int_overflow() { throw std::out_of_range("JSON integer does not fit in a signed 64-bit value"); }

Json& Json::set(const std::string& key, Json value) {
  auto* object = std::get_if<Object>(&value_);
  if (object == nullptr) throw std::logic_error(fmt::format("Json::set('{}') called on a value that is not an object", key));
  for (auto& [k, v] : *object) {
    if (k == key) {
      v = std::move(value);
      return *this;
    }
  }
  object->emplace_back(key, std::move(value));
  return *this;
}

Json& Json::push_back(Json value) {
  auto* array = std::get_if<Array>(&value_);
  if (array == nullptr) throw std::logic_error("Json::push_back called on a value that is not an array");
  array->push_back(std::move(value));
  return *this;
}

namespace {

// Invalid UTF-8 in a string (a scene name, a path) is written as U+FFFD rather than
// refused: a summary must be written whatever the input's bytes.
constexpr auto kInvalidUtf8 = nlohmann::ordered_json::error_handler_t::replace;

// The library's tree of the value, objects in insertion order. Throws
// std::invalid_argument naming the key path at a NaN or infinity, which the library
// would write as null.
nlohmann::ordered_json library_tree(const Json::Value& value, const std::string& path) {
  const std::string where = path.empty() ? "(top level)" : path;
  return std::visit(
      [&](const auto& v) -> nlohmann::ordered_json {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, double>) {
          if (!std::isfinite(v))
            throw std::invalid_argument(
                fmt::format("JSON value at '{}' is {}; only finite numbers can be written", where, v));
          return v;
        } else if constexpr (std::is_same_v<T, Json::Array>) {
          nlohmann::ordered_json a = nlohmann::ordered_json::array();
          for (std::size_t k = 0; k < v.size(); ++k) a.push_back(library_tree(v[k].value(), fmt::format("{}[{}]", path, k)));
          return a;
        } else if constexpr (std::is_same_v<T, Json::Object>) {
          nlohmann::ordered_json o = nlohmann::ordered_json::object();
          for (const auto& [key, member] : v) o[key] = library_tree(member.value(), path.empty() ? key : path + "." + key);
          return o;
        } else {
          return v;
        }
      },
      value);
}

}  // namespace

std::string json_quote(const std::string& s) { return nlohmann::ordered_json(s).dump(-1, ' ', false, kInvalidUtf8); }

std::string Json::dump(int indent) const {
  // The library writes integers as they are and doubles as the shortest text that reads
  // back to the same bits; indent <= 0 is one line.
  return library_tree(value_, "").dump(indent > 0 ? indent : -1, ' ', false, kInvalidUtf8);
}

void write_json_atomically(const std::filesystem::path& path, const Json& value, int indent) {
  write_text_atomically(path, value.dump(indent) + "\n");  // serialise first: a bad value never touches the file
}

}  // namespace rkpm::io
