#include "fuzz_targets.hpp"

#include "rkpm/particles/generators.hpp"
#include "rkpm/scene/scene.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>

namespace rkpm::fuzz {

Outcome scene_text(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    scene::parse_scene(text, "fuzz.toml");
    return Outcome::Accepted;
  } catch (const scene::SceneError&) {
    return Outcome::Refused;
  }
}

namespace {

// One file per process, rewritten for every input and removed at exit.
class TemporaryVtu {
 public:
  TemporaryVtu()
      : path_((std::filesystem::temp_directory_path() / ("rkpm-fuzz-" + std::to_string(::getpid()) + ".vtu"))
                  .string()) {}
  ~TemporaryVtu() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }
  TemporaryVtu(const TemporaryVtu&) = delete;
  TemporaryVtu& operator=(const TemporaryVtu&) = delete;

  const std::string& write(const std::uint8_t* data, std::size_t size) const {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    return path_;
  }

 private:
  std::string path_;
};

}  // namespace

Outcome vtu_file(const std::uint8_t* data, std::size_t size) {
  static const TemporaryVtu file;
  const std::string& path = file.write(data, size);
  try {
    particles::import_vtu(path);
    return Outcome::Accepted;
  } catch (const particles::CloudError&) {
    return Outcome::Refused;
  }
}

}  // namespace rkpm::fuzz
