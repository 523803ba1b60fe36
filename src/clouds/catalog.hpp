// The particle-cloud generators a scene can select, taken from catalog.def: the scene
// registry validates [body.cloud] tables against `cloud_tables()`, the loader, the
// nested levels, the pre-flight estimate and build_world reach a generator through
// the functions below. Nothing outside a generator's folder compares its name.
#pragma once

#include "rkpm/common/types.hpp"
#include "rkpm/particles/cloud.hpp"
#include "rkpm/scene/param_spec.hpp"

#include <string>
#include <vector>

namespace rkpm::scene {
struct BodySpec;
class ParamSet;
}  // namespace rkpm::scene

namespace rkpm::clouds {

// What a cloud will cost, before it is made (rkpm check, sim/preflight.hpp): its
// particles and elements, and the grid its supports are sized on.
struct CloudSize {
  double particles = 0.0;
  double elements = 0.0;
  Vec3 spacing = Vec3::Ones();   // mean particle spacing along x, y, z [m]
  Vec3 extent = Vec3::Ones();    // the cloud's extent along x, y, z [m]; infinite when unknown
  double longest_edge = 1.0;     // the longest element edge [m]
  std::string size_key;          // where the scene sets the size: "file:line: [body.cloud] key"
};

// Each generator's entry points.
//   table()           its [body.cloud] variant table (start from cloud_table()).
//   load(spec)        reads what the validated table names (a file, its surfaces) into
//                     the BodySpec; throws scene::SceneError naming the key.
//   rescale(p, f)     multiplies the table's cell counts by f (rounded, never below the
//                     generator's minimum) for a nested level; false when the cloud
//                     cannot be coarsened (an imported mesh), leaving p unchanged.
//   wall_thickness(p) the thickness of a shell's wall [m]; 0 for a solid cloud.
//   make(spec)        the cloud (rkpm_sim); throws particles::CloudError for a file.
//   estimate(spec)    its size, without making it (rkpm_sim); cheap, except that a
//                     Gmsh geometry is bounded by meshing it in a child process.
#define RKPM_CLOUD(generator)                                        \
  namespace generator {                                              \
  scene::ParamTable table();                                         \
  void load(scene::BodySpec& spec);                                  \
  bool rescale(scene::ParamSet& cloud, double factor);               \
  double wall_thickness(const scene::ParamSet& cloud);               \
  particles::Cloud make(const scene::BodySpec& spec);                \
  CloudSize estimate(const scene::BodySpec& spec);                   \
  }
#include "clouds/catalog.def"
#undef RKPM_CLOUD

// The scene side (rkpm_scene), dispatching on the body's generator.
std::vector<scene::ParamTable> cloud_tables();
void load_cloud(scene::BodySpec& spec);
bool rescale_cloud(scene::ParamSet& cloud, double factor);
bool can_rescale(const scene::BodySpec& spec);
double wall_thickness(const scene::BodySpec& spec);
// The simulation side (rkpm_sim).
particles::Cloud make_cloud(const scene::BodySpec& spec);
CloudSize estimate_cloud(const scene::BodySpec& spec);

// Helpers for the generators' folders.
// A [body.cloud] variant table with its selector set: the start of every generator's table.
scene::ParamTable cloud_table(std::string generator, std::string help);
// The largest cell count along one direction: the generators hold counts as int, and no
// cloud that fits a machine comes near it. What a count costs is checked before a run
// from the product (rkpm check).
constexpr double kMaxCells = 1 << 20;
// cells x factor, rounded, at least `smallest`.
std::int64_t scaled_cells(std::int64_t cells, double factor, std::int64_t smallest);
// "file:line: [section] key", where a pre-flight message points.
std::string key_at(const scene::ParamSet& p, const std::string& key);
// The path of the existing file named by key `key`, relative to the scene file's
// directory; throws scene::SceneError naming the key otherwise.
std::string existing_file(const scene::ParamSet& p, const std::string& key);

}  // namespace rkpm::clouds
