// generator = "block": its [body.cloud] table and its scaling (compiled into rkpm_scene).
#include "clouds/block/spec.hpp"

#include "rkpm/scene/scene.hpp"

namespace rkpm::clouds::block {

using scene::ParamSpec;

scene::ParamTable table() {
  scene::ParamTable t = cloud_table("block", "Rectangular block of hexahedra [origin, origin + size].");
  t.specs = {
      ParamSpec::vec3("origin", "m").defaults(Vec3::Zero()).help("Corner with the smallest coordinates."),
      ParamSpec::vec3("size", "m").greater_than(0).mark_required().help("Edge lengths along x, y, z."),
      ParamSpec::int3("cells").at_least(1).at_most(kMaxCells).mark_required().help("Number of hexahedra along x, y, z."),
      ParamSpec::real("jitter", "-").at_least(0).at_most(0.3).defaults(0.0)
          .help("Random offset of interior particles, as a fraction of the spacing (boundary "
                "particles stay on their faces)."),
      ParamSpec::integer("seed").at_least(0).defaults(std::int64_t{1}).help("Seed of the jitter."),
  };
  t.surfaces = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  return t;
}

particles::BlockSpec spec(const scene::BodySpec& body) {
  const scene::ParamSet& c = body.cloud;
  particles::BlockSpec s;
  s.origin = c.vec3("origin");
  s.size = c.vec3("size");
  const scene::Int3 cells = c.int3("cells");
  s.cells = {static_cast<int>(cells[0]), static_cast<int>(cells[1]), static_cast<int>(cells[2])};
  s.jitter = c.real("jitter");
  s.seed = static_cast<std::uint64_t>(c.integer("seed"));
  return s;
}

void load(scene::BodySpec&) {}

bool rescale(scene::ParamSet& cloud, double factor) {
  scene::Int3 cells = cloud.int3("cells");
  for (auto& c : cells) c = scaled_cells(c, factor, 1);
  cloud.set("cells", cells, cloud.table_line(), true);
  return true;
}

double wall_thickness(const scene::ParamSet&) { return 0.0; }

}  // namespace rkpm::clouds::block
