#include "sim_fixtures.hpp"

#include <omp.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace rkpm::sim::testing {

SceneWorld build_from_text(const std::string& toml, const std::string& name) {
  SceneWorld sw;
  sw.scene = scene::parse_scene(toml, name);
  sw.world = build_world(sw.scene);
  sw.settings = integrator_settings(sw.scene);
  return sw;
}

ScopedThreads::ScopedThreads(int n) : previous_(omp_get_max_threads()) { omp_set_num_threads(n); }
ScopedThreads::~ScopedThreads() { omp_set_num_threads(previous_); }

std::filesystem::path fresh_dir(const std::string& tag) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("rkpm_test_sim_" + tag + "_" + std::to_string(static_cast<long>(::getpid())));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string with(std::string text, const std::string& key, const std::string& value) {
  const std::string pattern = "{" + key + "}";
  auto at = text.find(pattern);
  if (at == std::string::npos) throw std::invalid_argument("with: '" + pattern + "' not in the scene text");
  while (at != std::string::npos) {
    text.replace(at, pattern.size(), value);
    at = text.find(pattern, at + value.size());
  }
  return text;
}

}  // namespace rkpm::sim::testing
