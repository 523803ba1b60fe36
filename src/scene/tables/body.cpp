// [[body]] and the sub-tables every body may have: RK approximation, initial state,
// boundary conditions. The cloud and the material are variant sections (the cloud
// catalog under src/clouds/; each model's params.cpp under src/materials/, collected by
// src/materials/catalog_tables.cpp), and a model may declare sub-tables of its own.
#include "tables/tables.hpp"

#include "rkpm/scene/param_set.hpp"

#include <string>

namespace rkpm::scene::tables {
namespace {

ParamTable rk_section() {
  ParamTable t;
  t.section = "body.rk";
  t.help = "Reproducing-kernel approximation and nodal integration of the body.";
  t.specs = {
      ParamSpec::choice("kernel", {"cubic", "quintic"}).defaults(std::string("cubic"))
          .help("Kernel function: cubic B-spline (C2) or quintic B-spline (C4)."),
      ParamSpec::real("support", "-").at_least(1.0).at_most(4.0).defaults(2.0)
          .help("Kernel support radius divided by the local particle spacing."),
      ParamSpec::choice("support_shape", {"auto", "sphere", "ellipsoid"}).defaults(std::string("auto"))
          .help("sphere: a ball of radius support x the particle's longest mesh edge. ellipsoid: "
                "shaped by the particle's mesh edges (support x the spacing in each direction), so a "
                "thin wall's supports reach as many spacings across it as along it and the operators "
                "stay short when the wall is refined in its plane. On a regular lattice both are the same. "
                "auto: ellipsoids on a generated cloud where a ball would hold more than 4 times the "
                "particles (a shell refined in its plane; `rkpm check` prints the choice), balls otherwise."),
      ParamSpec::choice("particle_order", {"input", "morton"}).defaults(std::string("morton"))
          .help("morton: renumbered along a Morton space-filling curve, so that particles near in space are "
                "near in memory and every operator row reads a compact range (faster steps), and a "
                "distributed run gives each rank a compact piece of the body (its range of this order). "
                "input: particles numbered as the generator or file gives them (a shell: layer by layer); "
                "ranks then own slabs of that order. Output frames list the particles in this order."),
      ParamSpec::choice("gradient_precision", {"double", "float"}).defaults(std::string("float"))
          .help("Storage of the smoothed gradients b_I(X_L), the largest operator: float (16 bytes per "
                "entry; every sum stays in double and F is formed from relative displacements, so a body "
                "at rest has F = I exactly and a linear field is reproduced to the float round-off, "
                "about 1e-7) or double (28 bytes). The default is float: the convergence study's errors "
                "agree with double storage to four digits (docs/verification/performance.md)."),
      ParamSpec::choice("basis", {"linear", "quadratic"}).defaults(std::string("linear"))
          .help("Polynomial basis the shape functions reproduce exactly."),
      ParamSpec::choice("integration", {"scni", "direct"}).defaults(std::string("scni"))
          .help("scni: stabilized conforming nodal integration over the cloud's dual cells "
                "(passes the patch test). direct: nodal gradients (unstable; for comparison only)."),
      ParamSpec::choice("cell_quadrature", {"corners", "centroids"}).defaults(std::string("corners"))
          .help("Quadrature of scni's smoothing-cell boundary integrals, on each planar triangle of a cell's "
                "surface; both are exact for linear fields (the patch test holds). corners: the shape "
                "functions at the triangle's corners, a third of its area each; the corners (edge "
                "midpoints, face and element centroids) are shared by up to eight cells, so a hexahedral "
                "cloud costs about 7 evaluations per particle (the set-up's largest part). centroids: at "
                "each triangle's centroid, about 24 per particle; slightly lower energy error, higher L2 "
                "error (docs/verification/convergence.md)."),
      ParamSpec::real("stabilization", "-").at_least(0).at_most(10).defaults(0.1)
          .help("Coefficient alpha of the interpolation-residual stabilization, which removes the "
                "spurious low-energy modes of nodal integration and leaves linear fields and rigid "
                "motions untouched (see rkpm/rk/stabilization.hpp); 0 = off."),
      ParamSpec::real("stabilization_reference_thickness", "m").at_least(0).defaults(0.0)
          .help("Wall thickness T_ref at which `stabilization` is given, for a shell cloud: at the "
                "cloud's thickness T the coefficient is alpha (T / T_ref)^2, so that with only the "
                "thickness changed the stabilization keeps its weight against the wall's bending "
                "stiffness (docs/theory/numerics.md). Within a factor 10 of T. 0 = alpha at any thickness."),
  };
  return t;
}

ParamTable initial_section() {
  ParamTable t;
  t.section = "body.initial";
  t.help = "Initial state of the body; the reference configuration is the generated cloud.";
  t.specs = {
      ParamSpec::vec3("velocity", "m/s").defaults(Vec3::Zero()).help("Uniform initial velocity."),
      ParamSpec::real("random_velocity", "m/s").at_least(0).defaults(0.0)
          .help("Amplitude of an added random velocity per particle and component, uniform in "
                "[-a, a], seeded by [integrator] seed."),
      ParamSpec::vec3("stretch", "-").greater_than(0).defaults(Vec3::Ones())
          .help("Initial homogeneous stretch about the body's centroid (principal stretches along x, y, z)."),
  };
  return t;
}

void check_boundary(ParamSet& p) {
  const std::string& axes = p.text("axes");
  bool ok = !axes.empty() && axes.size() <= 3;
  for (std::size_t i = 0; i < axes.size() && ok; ++i) {
    ok = (axes[i] == 'x' || axes[i] == 'y' || axes[i] == 'z') && axes.find(axes[i]) == i;
  }
  if (!ok) throw p.error("axes", "a non-empty subset of \"xyz\" with no repeated letter, e.g. \"xz\"");
  if (p.choice("type") == "fixed" && p.given("value")) {
    throw p.error("value", "no value unless type = \"velocity\" (fixed means zero displacement)");
  }
}

ParamTable boundary_section() {
  ParamTable t;
  t.section = "body.boundary";
  t.help = "Essential boundary condition on the particles of a named surface of the body's cloud.";
  t.specs = {
      ParamSpec::text("surface").mark_required().refers_to(Reference::surface)
          .help("A surface of the body's cloud generator, or \"all\" for every boundary particle."),
      ParamSpec::choice("type", {"fixed", "velocity"}).defaults(std::string("fixed"))
          .help("fixed: the listed displacement components stay zero. velocity: they move at `value`."),
      ParamSpec::vec3("value", "m/s").defaults(Vec3::Zero()).help("Prescribed velocity (type = velocity)."),
      ParamSpec::text("axes").defaults(std::string("xyz")).help("Constrained components: a subset of \"xyz\"."),
  };
  t.finish = check_boundary;
  return t;
}

}  // namespace

ParamTable body() {
  ParamTable t;
  t.section = "body";
  t.help = "A deformable body: a particle cloud, a material, initial fields and boundary conditions.";
  t.specs = {
      ParamSpec::text("name").mark_required().help("Unique name; terms refer to the body by it."),
      ParamSpec::real("density", "kg/m^3").greater_than(0).defaults(1000.0).help("Reference mass density rho0."),
  };
  return t;
}

std::vector<ParamTable> body_details() {
  return {rk_section(), initial_section(), boundary_section()};
}

}  // namespace rkpm::scene::tables
