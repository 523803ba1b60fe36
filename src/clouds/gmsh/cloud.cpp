// generator = "gmsh": the cloud and its size (compiled into rkpm_sim).
#include "clouds/gmsh/spec.hpp"

#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/preflight.hpp"

#include <fmt/format.h>

#include <limits>

namespace rkpm::clouds::gmsh {

particles::Cloud make(const scene::BodySpec& body) { return particles::import_gmsh(spec(body)); }

// Its nodes (.msh) or a bound from its bounding box and mesh size (.geo); the spacing
// is unknown, as for a .vtu.
CloudSize estimate(const scene::BodySpec& body) {
  const scene::ParamSet& c = body.cloud;
  CloudSize e;
  try {
    e.particles = particles::gmsh_particle_estimate(spec(body));
  } catch (const particles::CloudError& error) {  // a file Gmsh cannot read is bad input
    throw sim::PreflightError(fmt::format("{}: {}", key_at(c, "file"), error.what()));
  }
  e.elements = 6.0 * e.particles;
  e.extent = Vec3::Constant(std::numeric_limits<double>::infinity());
  e.size_key = fmt::format("{} (\"{}\")", key_at(c, c.has("mesh_size") ? "mesh_size" : "file"), body.cloud_file);
  return e;
}

}  // namespace rkpm::clouds::gmsh
