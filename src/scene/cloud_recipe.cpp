#include "rkpm/scene/cloud_recipe.hpp"

#include <stdexcept>

namespace rkpm::scene {

CloudRecipe cloud_recipe(const BodySpec& body) {
  const ParamSet& c = body.cloud;
  const std::string& generator = body.generator();
  if (generator == "block") {
    particles::BlockSpec spec;
    spec.origin = c.vec3("origin");
    spec.size = c.vec3("size");
    const Int3 cells = c.int3("cells");
    spec.cells = {static_cast<int>(cells[0]), static_cast<int>(cells[1]), static_cast<int>(cells[2])};
    spec.jitter = c.real("jitter");
    spec.seed = static_cast<std::uint64_t>(c.integer("seed"));
    return spec;
  }
  if (generator == "sphere") {
    particles::SphereSpec spec;
    spec.center = c.vec3("center");
    spec.radius = c.real("radius");
    spec.cells = static_cast<int>(c.integer("cells"));
    return spec;
  }
  if (generator == "shell") {
    particles::ShellSpec spec;
    spec.center = c.vec3("center");
    spec.semi_axes = c.vec3("semi_axes");
    spec.thickness = c.real("thickness");
    spec.face_cells = static_cast<int>(c.integer("face_cells"));
    spec.layers = static_cast<int>(c.integer("layers"));
    return spec;
  }
  if (generator == "vtu") return VtuImport{body.cloud_file, c.real("scale")};
  if (generator == "gmsh")
    return particles::GmshImportSpec{body.cloud_file, c.real("scale"), c.has("mesh_size") ? c.real("mesh_size") : 0.0,
                                     c.flag("trusted")};
  throw std::logic_error("cloud_recipe: generator \"" + generator + "\" is registered but has no recipe");
}

}  // namespace rkpm::scene
