// Shared helpers of the simulation tests: worlds built from inline scene text,
// stepping, and the measures the tests compare with closed-form answers.
#pragma once

#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/build.hpp"
#include "rkpm/sim/integrator.hpp"
#include "rkpm/sim/world.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

namespace rkpm::sim::testing {

// A scene and the world built from it; the scene must outlive the world only
// while building, but keeping both together makes the tests read simply.
struct SceneWorld {
  scene::Scene scene;
  std::unique_ptr<World> world;
  IntegratorSettings settings;
};

// Parses `toml` (display name `name`) and builds its world and integrator settings.
SceneWorld build_from_text(const std::string& toml, const std::string& name = "test.toml");

// A fresh, empty directory under the system temporary directory, unique to `tag`
// and the process.
std::filesystem::path fresh_dir(const std::string& tag);

// Sets the OpenMP thread count for its lifetime. The numerical tests run on one
// thread: a loaded machine makes OpenMP barriers very slow, and the results do not
// depend on it (the restart test checks the thread-count contract separately).
class ScopedThreads {
 public:
  explicit ScopedThreads(int n);
  ~ScopedThreads();
  ScopedThreads(const ScopedThreads&) = delete;
  ScopedThreads& operator=(const ScopedThreads&) = delete;

 private:
  int previous_;
};

// Writes `text` to `path` (creating parent directories).
void write_text(const std::filesystem::path& path, const std::string& text);

// Everything in a file, as text.
std::string read_text(const std::filesystem::path& path);

// `text` with every "{key}" replaced by `value`; throws if the key is absent so
// that a test cannot silently run an unmodified scene.
std::string with(std::string text, const std::string& key, const std::string& value);

}  // namespace rkpm::sim::testing
