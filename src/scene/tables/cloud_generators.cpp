// Variants of [body.cloud]: one table per particle-cloud generator of
// rkpm/particles/generators.hpp, with the surfaces each cloud provides.
#include "tables/tables.hpp"

#include "rkpm/scene/param_set.hpp"

#include <fmt/format.h>

namespace rkpm::scene::tables {
namespace {

// The largest cell count along one direction: the generators hold counts as int, and
// no cloud that fits a machine comes near it. What a count costs in particles, memory
// and output is checked before a run from the product (rkpm check, sim/preflight.hpp).
constexpr double kMaxCells = 1 << 20;

ParamTable variant(std::string name, std::string help) {
  ParamTable t;
  t.section = "body.cloud";
  t.selector_key = "generator";
  t.selector_value = std::move(name);
  t.help = std::move(help);
  return t;
}

ParamTable block() {
  ParamTable t = variant("block", "Rectangular block of hexahedra [origin, origin + size].");
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

ParamTable sphere() {
  ParamTable t = variant("sphere", "Solid ball of hexahedra (a cube mapped onto the ball).");
  t.specs = {
      ParamSpec::vec3("center", "m").defaults(Vec3::Zero()).help("Centre of the ball."),
      ParamSpec::real("radius", "m").greater_than(0).mark_required().help("Radius of the ball."),
      ParamSpec::integer("cells").at_least(2).at_most(kMaxCells).defaults(std::int64_t{16}).help("Hexahedra across a diameter."),
  };
  t.surfaces = {"surface"};
  return t;
}

ParamTable shell() {
  ParamTable t = variant("shell", "Closed thick ellipsoidal shell (the seed's red-blood-cell model, Sec. 4.1).");
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
  t.finish = [](ParamSet& p) {
    const double smallest = p.vec3("semi_axes").minCoeff();
    if (p.real("thickness") >= smallest) {
      throw p.error("thickness", fmt::format("a thickness smaller than the smallest semi-axis ({} m)",
                                             format_value(smallest)));
    }
  };
  return t;
}

ParamTable vtu() {
  ParamTable t = variant("vtu", "Nodes and tetrahedra/hexahedra of a VTK unstructured-grid file.");
  t.specs = {
      ParamSpec::text("file").mark_required()
          .help("Path of the .vtu file, relative to the scene file's directory."),
      ParamSpec::real("scale", "-").greater_than(0).defaults(1.0)
          .help("Factor applied to the file's coordinates (1e-6 for a mesh written in micrometres)."),
  };
  t.surfaces = {"surface"};
  return t;
}

// The surfaces of a Gmsh cloud are its file's physical surfaces: the loader reads them
// (BodySpec::file_surfaces), so the table lists only the whole boundary.
ParamTable gmsh() {
  ParamTable t = variant("gmsh", "A Gmsh mesh (.msh: tetrahedra and hexahedra, first or second order) or geometry "
                                 "(.geo, meshed with mesh_size), read through Gmsh's C++ API.");
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

}  // namespace

std::vector<ParamTable> cloud_generators() { return {block(), sphere(), shell(), vtu(), gmsh()}; }

}  // namespace rkpm::scene::tables
