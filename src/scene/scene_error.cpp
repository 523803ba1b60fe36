#include "rkpm/scene/scene_error.hpp"

#include <fmt/format.h>

#include <utility>

namespace rkpm::scene {
namespace {

std::string located(const std::string& file, int line, const std::string& rest) {
  return line > 0 ? fmt::format("{}:{}: {}", file, line, rest) : fmt::format("{}: {}", file, rest);
}

std::string standard_message(const std::string& section, const std::string& key,
                             const std::string& value, const std::string& expected) {
  std::string where = fmt::format("[{}]", section);
  if (!key.empty()) where += " " + key;
  if (!key.empty() && !value.empty()) where += " = " + value;
  return fmt::format("{}: expected {}", where, expected);
}

}  // namespace

SceneError::SceneError(std::string file, int line, const std::string& message)
    : std::runtime_error(located(file, line, message)), file_(std::move(file)), line_(line) {}

SceneError::SceneError(std::string file, int line, const std::string& section,
                       const std::string& key, const std::string& value,
                       const std::string& expected)
    : SceneError(std::move(file), line, standard_message(section, key, value, expected)) {}

}  // namespace rkpm::scene
