#include "rkpm/scene/param_set.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <utility>

namespace rkpm::scene {

ParamSet::ParamSet(std::vector<const ParamTable*> tables, std::string file, int line, std::string section)
    : tables_(std::move(tables)), file_(std::move(file)), line_(line), section_(std::move(section)) {}

const ParamSpec& ParamSet::spec(const std::string& name) const {
  for (const ParamTable* table : tables_) {
    if (const ParamSpec* s = table->find(name)) return *s;
  }
  throw std::logic_error(fmt::format("parameter '{}' is not declared in [{}]", name, section_));
}

const ParamSet::Entry& ParamSet::entry(const std::string& name, ParamType type) const {
  const ParamSpec& s = spec(name);
  // A choice is also a string, so text() may read it.
  const bool compatible = s.type == type || (type == ParamType::text && s.type == ParamType::choice);
  if (!compatible) {
    throw std::logic_error(fmt::format("parameter [{}] {} is a {}, not a {}", section_, name,
                                       type_name(s.type), type_name(type)));
  }
  const auto it = values_.find(name);
  if (it == values_.end()) {
    throw std::logic_error(fmt::format("parameter [{}] {} has no value (check has() first)", section_, name));
  }
  return it->second;
}

double ParamSet::real(const std::string& name) const { return std::get<double>(entry(name, ParamType::real).value); }
std::int64_t ParamSet::integer(const std::string& name) const { return std::get<std::int64_t>(entry(name, ParamType::integer).value); }
bool ParamSet::flag(const std::string& name) const { return std::get<bool>(entry(name, ParamType::boolean).value); }
const std::string& ParamSet::text(const std::string& name) const { return std::get<std::string>(entry(name, ParamType::text).value); }
const std::string& ParamSet::choice(const std::string& name) const { return std::get<std::string>(entry(name, ParamType::choice).value); }
Vec3 ParamSet::vec3(const std::string& name) const { return std::get<Vec3>(entry(name, ParamType::vec3).value); }
Int3 ParamSet::int3(const std::string& name) const { return std::get<Int3>(entry(name, ParamType::int3).value); }
const std::vector<std::string>& ParamSet::texts(const std::string& name) const {
  return std::get<std::vector<std::string>>(entry(name, ParamType::text_list).value);
}
const std::vector<double>& ParamSet::reals(const std::string& name) const {
  return std::get<std::vector<double>>(entry(name, ParamType::real_list).value);
}

bool ParamSet::has(const std::string& name) const {
  spec(name);
  return values_.count(name) != 0;
}

bool ParamSet::given(const std::string& name) const {
  spec(name);
  const auto it = values_.find(name);
  return it != values_.end() && it->second.given;
}

int ParamSet::line(const std::string& name) const {
  spec(name);
  const auto it = values_.find(name);
  return it != values_.end() ? it->second.line : line_;
}

std::string ParamSet::variant() const {
  for (const ParamTable* table : tables_) {
    if (!table->selector_value.empty()) return table->selector_value;
  }
  return {};
}

void ParamSet::set(const std::string& name, ParamValue value, int line, bool given) {
  spec(name);
  values_[name] = Entry{std::move(value), line, given};
}

SceneError ParamSet::error(const std::string& name, const std::string& expected) const {
  const auto it = values_.find(name);
  const std::string value = it != values_.end() ? format_value(it->second.value) : std::string();
  return SceneError(file_, line(name), section_, name, value, expected);
}

}  // namespace rkpm::scene
