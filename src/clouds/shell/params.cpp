// generator = "shell": its [body.cloud] table and its scaling (compiled into rkpm_scene).
#include "clouds/shell/spec.hpp"

#include "rkpm/scene/scene.hpp"

#include <fmt/format.h>

namespace rkpm::clouds::shell {

using scene::ParamSpec;

scene::ParamTable table() {
  scene::ParamTable t =
      cloud_table("shell", "Closed thick ellipsoidal shell (the seed's red-blood-cell model, Sec. 4.1).");
  t.specs = {
      ParamSpec::vec3("center", "m").defaults(Vec3::Zero()).help("Centre of the ellipsoid."),
      ParamSpec::vec3("semi_axes", "m").greater_than(0).defaults(Vec3(5e-6, 5e-6, 1.5e-6))
          .help("Semi-axes of the outer surface."),
      ParamSpec::real("thickness", "m").greater_than(0).defaults(0.5e-6)
          .help("Wall thickness: the inner surface has every semi-axis reduced by it."),
      ParamSpec::integer("face_cells").at_least(2).at_most(kMaxCells).defaults(std::int64_t{32})
          .help("Cells along each edge of the 6 cubed-sphere faces."),
      ParamSpec::integer("layers").at_least(2).at_most(kMaxCells).defaults(std::int64_t{5}).help("Particle layers through the wall."),
  };
  t.surfaces = {"outer", "inner"};
  t.finish = [](scene::ParamSet& p) {
    const double smallest = p.vec3("semi_axes").minCoeff();
    if (p.real("thickness") >= smallest) {
      throw p.error("thickness", fmt::format("a thickness smaller than the smallest semi-axis ({} m)",
                                             scene::format_value(smallest)));
    }
  };
  return t;
}

particles::ShellSpec spec(const scene::BodySpec& body) {
  const scene::ParamSet& c = body.cloud;
  particles::ShellSpec s;
  s.center = c.vec3("center");
  s.semi_axes = c.vec3("semi_axes");
  s.thickness = c.real("thickness");
  s.face_cells = static_cast<int>(c.integer("face_cells"));
  s.layers = static_cast<int>(c.integer("layers"));
  return s;
}

void load(scene::BodySpec&) {}

// A shell keeps its layers: the driver of the red-blood-cell scene acts on halves of the
// wall, so the layer count is part of the model, not of the resolution.
bool rescale(scene::ParamSet& cloud, double factor) {
  cloud.set("face_cells", scaled_cells(cloud.integer("face_cells"), factor, 2), cloud.table_line(), true);
  return true;
}

double wall_thickness(const scene::ParamSet& cloud) { return cloud.real("thickness"); }

}  // namespace rkpm::clouds::shell
