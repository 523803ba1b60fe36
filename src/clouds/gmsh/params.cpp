// generator = "gmsh": its [body.cloud] table and its file's surfaces (compiled into
// rkpm_scene).
#include "clouds/gmsh/spec.hpp"

#include "rkpm/scene/scene.hpp"

#include <filesystem>

namespace rkpm::clouds::gmsh {

using scene::ParamSpec;

// The surfaces of a Gmsh cloud are its file's physical surfaces: load() reads them
// (BodySpec::file_surfaces), so the table lists only the whole boundary.
scene::ParamTable table() {
  scene::ParamTable t = cloud_table("gmsh", "A Gmsh mesh (.msh: tetrahedra and hexahedra, first or second order) or "
                                            "geometry (.geo, meshed with mesh_size), read through Gmsh's C++ API.");
  t.specs = {
      ParamSpec::text("file").mark_required()
          .help("Path of the .msh or .geo file, relative to the scene file's directory. Its physical groups of "
                "dimension 2 are the body's named surfaces, beside \"surface\" (the whole boundary)."),
      ParamSpec::real("scale", "-").greater_than(0).defaults(1.0)
          .help("Factor applied to the file's coordinates (1e-6 for a geometry written in micrometres)."),
      ParamSpec::real("mesh_size", "m").greater_than(0).absent_means("required for .geo")
          .help("Largest element edge of the mesh made from a .geo file, in the file's units (before scale). "
                "Not used for a .msh file."),
      ParamSpec::boolean("trusted").defaults(false)
          .help("A .geo file is a program. Unless true, one that runs commands (SystemCall), ends the "
                "process (Exit), reads other files (Include, Merge), loops (For, While), calls macros or "
                "sets Mesh.* options is refused. Set it only for a file you wrote or checked."),
  };
  t.surfaces = {"surface"};
  return t;
}

particles::GmshImportSpec spec(const scene::BodySpec& body) {
  const scene::ParamSet& c = body.cloud;
  return particles::GmshImportSpec{body.cloud_file, c.real("scale"), c.has("mesh_size") ? c.real("mesh_size") : 0.0,
                                   c.flag("trusted")};
}

void load(scene::BodySpec& spec) {
  const scene::ParamSet& c = spec.cloud;
  spec.cloud_file = existing_file(c, "file");
  const std::string extension = std::filesystem::path(spec.cloud_file).extension().string();
  if (extension != ".msh" && extension != ".geo")
    throw c.error("file", "a Gmsh file named *.msh (a mesh) or *.geo (a geometry to mesh)");
  if (extension == ".geo" && !c.has("mesh_size"))
    throw c.error("file", "a mesh_size key beside a .geo file: the largest element edge to mesh it with");
  try {
    spec.file_surfaces = particles::gmsh_surface_names(spec.cloud_file, c.flag("trusted"));
  } catch (const particles::CloudError& e) {
    throw c.error("file", std::string("a file Gmsh can read: ") + e.what());
  }
}

// An imported mesh cannot be coarsened.
bool rescale(scene::ParamSet&, double) { return false; }

double wall_thickness(const scene::ParamSet&) { return 0.0; }

}  // namespace rkpm::clouds::gmsh
