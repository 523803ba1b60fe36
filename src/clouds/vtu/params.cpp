// generator = "vtu": its [body.cloud] table and its file (compiled into rkpm_scene).
#include "clouds/vtu/spec.hpp"

#include "rkpm/scene/scene.hpp"

namespace rkpm::clouds::vtu {

using scene::ParamSpec;

scene::ParamTable table() {
  scene::ParamTable t = cloud_table("vtu", "Nodes and tetrahedra/hexahedra of a VTK unstructured-grid file.");
  t.specs = {
      ParamSpec::text("file").mark_required()
          .help("Path of the .vtu file, relative to the scene file's directory."),
      ParamSpec::real("scale", "-").greater_than(0).defaults(1.0)
          .help("Factor applied to the file's coordinates (1e-6 for a mesh written in micrometres)."),
  };
  t.surfaces = {"surface"};
  return t;
}

Import spec(const scene::BodySpec& body) { return Import{body.cloud_file, body.cloud.real("scale")}; }

void load(scene::BodySpec& spec) { spec.cloud_file = existing_file(spec.cloud, "file"); }

// An imported mesh cannot be coarsened.
bool rescale(scene::ParamSet&, double) { return false; }

double wall_thickness(const scene::ParamSet&) { return 0.0; }

}  // namespace rkpm::clouds::vtu
