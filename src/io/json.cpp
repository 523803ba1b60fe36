#include "rkpm/io/json.hpp"

#include "rkpm/io/atomic_file.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

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

std::string json_quote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          out += fmt::format("\\u{:04x}", static_cast<unsigned>(static_cast<unsigned char>(c)));
        } else {
          out += c;
        }
    }
  }
  out += '"';
  return out;
}

namespace {

void newline(std::string& out, int indent, int depth) {
  if (indent <= 0) return;
  out += '\n';
  out.append(static_cast<std::size_t>(indent * depth), ' ');
}

}  // namespace

void Json::dump_to(std::string& out, int indent, int depth, const std::string& path) const {
  const std::string where = path.empty() ? "(top level)" : path;
  if (std::holds_alternative<std::nullptr_t>(value_)) {
    out += "null";
  } else if (const bool* b = std::get_if<bool>(&value_)) {
    out += *b ? "true" : "false";
  } else if (const std::int64_t* i = std::get_if<std::int64_t>(&value_)) {
    out += fmt::format("{}", *i);
  } else if (const double* x = std::get_if<double>(&value_)) {
    if (!std::isfinite(*x)) {
      throw std::invalid_argument(fmt::format("JSON value at '{}' is {}; only finite numbers can be written", where, *x));
    }
    out += fmt::format("{}", *x);  // shortest round-trip representation, locale-independent
  } else if (const std::string* s = std::get_if<std::string>(&value_)) {
    out += json_quote(*s);
  } else if (const Array* a = std::get_if<Array>(&value_)) {
    out += '[';
    for (std::size_t k = 0; k < a->size(); ++k) {
      if (k > 0) out += ',';
      newline(out, indent, depth + 1);
      (*a)[k].dump_to(out, indent, depth + 1, fmt::format("{}[{}]", path, k));
    }
    if (!a->empty()) newline(out, indent, depth);
    out += ']';
  } else {
    const Object& o = std::get<Object>(value_);
    out += '{';
    for (std::size_t k = 0; k < o.size(); ++k) {
      if (k > 0) out += ',';
      newline(out, indent, depth + 1);
      out += json_quote(o[k].first);
      out += indent > 0 ? ": " : ":";
      o[k].second.dump_to(out, indent, depth + 1, path.empty() ? o[k].first : path + "." + o[k].first);
    }
    if (!o.empty()) newline(out, indent, depth);
    out += '}';
  }
}

std::string Json::dump(int indent) const {
  std::string out;
  dump_to(out, indent, 0, "");
  return out;
}

void write_json_atomically(const std::filesystem::path& path, const Json& value, int indent) {
  write_text_atomically(path, value.dump(indent) + "\n");  // serialise first: a bad value never touches the file
}

}  // namespace rkpm::io
