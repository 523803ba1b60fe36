// generator = "sphere": its [body.cloud] table and its scaling (compiled into rkpm_scene).
#include "clouds/sphere/spec.hpp"

#include "rkpm/scene/scene.hpp"

namespace rkpm::clouds::sphere {

using scene::ParamSpec;

scene::ParamTable table() {
  scene::ParamTable t = cloud_table("sphere", "Solid ball of hexahedra (a cube mapped onto the ball).");
  t.specs = {
      ParamSpec::vec3("center", "m").defaults(Vec3::Zero()).help("Centre of the ball."),
      ParamSpec::real("radius", "m").greater_than(0).mark_required().help("Radius of the ball."),
      ParamSpec::integer("cells").at_least(2).at_most(kMaxCells).defaults(std::int64_t{16}).help("Hexahedra across a diameter."),
  };
  t.surfaces = {"surface"};
  return t;
}

particles::SphereSpec spec(const scene::BodySpec& body) {
  const scene::ParamSet& c = body.cloud;
  particles::SphereSpec s;
  s.center = c.vec3("center");
  s.radius = c.real("radius");
  s.cells = static_cast<int>(c.integer("cells"));
  return s;
}

void load(scene::BodySpec&) {}

bool rescale(scene::ParamSet& cloud, double factor) {
  cloud.set("cells", scaled_cells(cloud.integer("cells"), factor, 2), cloud.table_line(), true);
  return true;
}

double wall_thickness(const scene::ParamSet&) { return 0.0; }

}  // namespace rkpm::clouds::sphere
