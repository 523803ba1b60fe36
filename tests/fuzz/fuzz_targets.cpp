#include "fuzz_targets.hpp"

#include "rkpm/particles/generators.hpp"
#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/build.hpp"
#include "rkpm/sim/checkpoint.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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

// One file per process and extension, rewritten for every input and removed at exit.
class TemporaryFile {
 public:
  explicit TemporaryFile(const std::string& extension)
      : path_((std::filesystem::temp_directory_path() /
               ("rkpm-fuzz-" + std::to_string(::getpid()) + extension))
                  .string()) {}
  ~TemporaryFile() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  const std::string& path() const { return path_; }

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
  static const TemporaryFile file(".vtu");
  const std::string& path = file.write(data, size);
  try {
    particles::import_vtu(path);
    return Outcome::Accepted;
  } catch (const particles::CloudError&) {
    return Outcome::Refused;
  }
}

template <class Import>
Outcome refused_as_cloud_error(Import import) {
  try {
    import();
    return Outcome::Accepted;
  } catch (const particles::CloudError&) {
    return Outcome::Refused;
  }
}

Outcome msh_file(const std::uint8_t* data, std::size_t size) {
  static const TemporaryFile file(".msh");
  const std::string& path = file.write(data, size);
  return refused_as_cloud_error([&] { particles::import_gmsh({path, 1.0, 0.0, false}); });
}

Outcome geo_file(const std::uint8_t* data, std::size_t size) {
  static const TemporaryFile file(".geo");
  const std::string& path = file.write(data, size);
  const particles::GmshImportSpec spec{path, 1.0, 0.25, false};
  return refused_as_cloud_error([&] {
    if (particles::gmsh_particle_estimate(spec) > kGeoNodeBudget)
      throw particles::CloudError("over the fuzz target's node budget");
    particles::import_gmsh(spec);
  });
}

namespace {

// A small world with what a checkpoint carries: an LCE body with its director, a
// Mooney-Rivlin block with a fixed face (constraint targets), a contact term and FIRE
// state in the integrator. s0 holds the block's 2 um grid (holding.hpp); the cell
// starts 1 um above the block.
constexpr std::string_view kCheckpointScene = R"([scene]
name = "fuzz_checkpoint"
[integrator]
mode = "dynamic"
t_end = 1e-6
damping = 1e5
[[body]]
name = "cell"
[body.cloud]
generator = "sphere"
center = [0, 0, 5e-6]
radius = 2e-6
cells = 4
[body.material]
model = "lce"
mu = 1e4
bulk = 1e5
s = 2.0
kappa = 1e-11
[body.director]
initial = "surface_normal"
[[body]]
name = "block"
[body.cloud]
generator = "block"
origin = [-3e-6, -3e-6, 0]
size = [6e-6, 6e-6, 2e-6]
cells = [3, 3, 1]
[body.material]
model = "mooney_rivlin"
c1 = 2e3
lambda = 1e5
[[body.boundary]]
surface = "zmin"
[[term]]
type = "contact"
bodies = ["cell", "block"]
s0 = 1.5e-6
epsilon = 3e-15
beta = [1e18, 1e18]
)";
constexpr std::uint64_t kCheckpointSceneDigest = 0x5eedc0ffee;

struct CheckpointWorld {
  std::unique_ptr<sim::World> world;
  std::unique_ptr<sim::Integrator> integrator;
};

CheckpointWorld checkpoint_world() {
  static const scene::Scene scene = scene::parse_scene(kCheckpointScene, "fuzz_checkpoint.toml");
  CheckpointWorld w;
  w.world = sim::build_world(scene);
  w.integrator = std::make_unique<sim::Integrator>(*w.world, sim::integrator_settings(scene));
  w.integrator->initialize();
  return w;
}

std::uint64_t fnv1a(const std::string& bytes) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  return h;
}

bool all_finite(const std::vector<Vec3>& values) {
  for (const Vec3& v : values)
    if (!(std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()))) return false;
  return true;
}

}  // namespace

std::string checkpoint_seed() {
  CheckpointWorld w = checkpoint_world();
  for (int k = 0; k < 3; ++k) w.integrator->step();
  static const TemporaryFile file(".seed.bin");
  const std::string& path = file.path();
  sim::write_checkpoint(path, *w.world, *w.integrator, sim::RunClock{}, kCheckpointSceneDigest);
  std::ifstream in(path, std::ios::binary);
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  bytes.resize(bytes.size() - sizeof(std::uint64_t));  // the closing digest, which the target adds
  return bytes;
}

Outcome checkpoint_file(const std::uint8_t* data, std::size_t size) {
  static const TemporaryFile file(".ckpt");
  std::string sealed(reinterpret_cast<const char*>(data), size);
  const std::uint64_t digest = fnv1a(sealed);
  sealed.append(reinterpret_cast<const char*>(&digest), sizeof digest);
  const std::string& path = file.write(reinterpret_cast<const std::uint8_t*>(sealed.data()), sealed.size());

  CheckpointWorld w = checkpoint_world();
  sim::RunClock clock;
  try {
    sim::read_checkpoint(path, *w.world, *w.integrator, clock, kCheckpointSceneDigest);
  } catch (const std::runtime_error& e) {
    // read_checkpoint's refusals name the file; any other error escaping is a bug.
    if (std::strncmp(e.what(), "checkpoint ", 11) == 0) return Outcome::Refused;
    throw;
  }
  // What an accepted checkpoint leaves must be a state the run can go on from.
  bool finite = std::isfinite(w.world->time) && std::isfinite(w.integrator->dt()) && w.integrator->dt() > 0.0;
  for (const auto& b : w.world->bodies) {
    finite = finite && all_finite(b->d) && all_finite(b->v) && all_finite(b->force);
    if (materials::lce::material_of(*b)) finite = finite && all_finite(materials::lce::material_of(*b)->director.h);
  }
  if (!finite) {
    std::fputs("checkpoint_file: an accepted checkpoint left a non-finite state\n", stderr);
    std::abort();
  }
  return Outcome::Accepted;
}

}  // namespace rkpm::fuzz
