// The scenes the benchmarks and the scaling study measure, at any resolution.
//
// Three geometries, each with the physics its example declares:
//   block   Mooney-Rivlin cube (the adhesion substrate's material), base fixed,
//           under a body force: the passive solid;
//   sphere  LCE ball with the Frank term, surface-normal director and surface
//           tension (the adhesion scene's cell, alone): the active solid;
//   shell   examples/rbc/rbc.toml with face_cells refined at fixed layers: the
//           thick LCE shell with its volume constraint.
// Scenes are built through scene::parse_scene, so they pass the same validation as
// a user's file and build_world builds exactly what a run would.
#pragma once

#include "rkpm/scene/scene.hpp"

#include <string>

namespace rkpm::bench {

enum class Geometry { Block, Sphere, Shell };

const char* geometry_name(Geometry g);
Geometry parse_geometry(const std::string& name);  // throws std::invalid_argument

// The resolution parameter of a geometry (block and sphere: cells per edge or
// diameter; shell: face_cells at `shell_layers` layers) whose particle count is
// closest to `target`, and the particle count it gives.
constexpr int shell_layers = 5;
int resolution_for(Geometry g, double target);
long long particles_at(Geometry g, int resolution);

// The [body.rk] keys a study declares in every geometry's scene (the values of the
// scene format's choices; the defaults are the format's own).
struct RkChoices {
  std::string support_shape = "sphere";        // sphere | ellipsoid
  std::string particle_order = "input";        // input | morton
  std::string gradient_precision = "float";    // float | double
};

// The scene at a resolution, with the [body.rk] keys of `rk`. The shell is read from
// `rbc_scene` (examples/rbc/rbc.toml) and rewritten; relative paths inside it resolve
// against its directory.
scene::Scene make_scene(Geometry g, int resolution, const std::string& rbc_scene, const RkChoices& rk = {});

// A file of the source tree (examples/...): under $RKPM_SOURCE_DIR when set, else
// under the source directory the program was configured from.
std::string source_file(const std::string& relative);

}  // namespace rkpm::bench
