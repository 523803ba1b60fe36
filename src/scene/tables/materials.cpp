// Variants of [body.material]: one table per constitutive model.
#include "tables/tables.hpp"

#include "rkpm/scene/param_set.hpp"

namespace rkpm::scene::tables {
namespace {

ParamTable variant(std::string name, std::string help) {
  ParamTable t;
  t.section = "body.material";
  t.selector_key = "model";
  t.selector_value = std::move(name);
  t.help = std::move(help);
  return t;
}

void check_mooney_rivlin(ParamSet& p) {
  if (p.real("c1") + p.real("c2") <= 0.0) throw p.error("c2", "c1 + c2 > 0 (both are zero)");
  const char* grade_keys[] = {"grade_a", "grade_b", "grade_length"};
  if (p.choice("grade_axis") == "none") {
    for (const char* key : grade_keys) {
      if (p.given(key)) throw p.error(key, "no grading key unless grade_axis is \"x\", \"y\" or \"z\"");
    }
    return;
  }
  // The factor a*s + b (s = 0 at the body's minimum, 1 at grade_length) scales
  // positive moduli; it must stay positive at both ends of the body.
  const double a = p.real("grade_a"), b = p.real("grade_b");
  if (b <= 0.0) throw p.error("grade_b", "grade_b > 0 (the factor a*s + b must stay positive at s = 0)");
  if (a + b <= 0.0) throw p.error("grade_a", "grade_a + grade_b > 0 (the factor a*s + b must stay positive at s = 1)");
}

ParamTable mooney_rivlin() {
  ParamTable t = variant("mooney_rivlin",
                         "Compressible Mooney-Rivlin solid (seed Eq. 9-11), optionally graded along an "
                         "axis (Eq. 18): every modulus is multiplied by a*s + b, s = (X_axis - X_min) / L0.");
  t.specs = {
      ParamSpec::real("c1", "Pa").at_least(0).mark_required().help("First Mooney-Rivlin constant (Eq. 9)."),
      ParamSpec::real("c2", "Pa").at_least(0).defaults(0.0).help("Second Mooney-Rivlin constant (Eq. 9)."),
      ParamSpec::real("lambda", "Pa").greater_than(0).mark_required()
          .help("Volumetric constant of the (ln I3)^2 term (Eq. 9)."),
      ParamSpec::choice("grade_axis", {"none", "x", "y", "z"}).defaults(std::string("none"))
          .help("Axis along which the moduli vary (Eq. 18 uses y); none = homogeneous."),
      ParamSpec::real("grade_a", "-").defaults(0.0).help("Slope a of the grading factor a*s + b (Eq. 18: 4)."),
      ParamSpec::real("grade_b", "-").defaults(1.0).help("Offset b of the grading factor a*s + b (Eq. 18: 0.5)."),
      ParamSpec::real("grade_length", "m").at_least(0).defaults(0.0)
          .help("Length L0 over which s goes from 0 to 1; 0 = the body's extent along the axis."),
  };
  t.finish = check_mooney_rivlin;
  return t;
}

ParamTable lce() {
  ParamTable t = variant("lce",
                         "Active liquid-crystal elastomer (seed Eq. 1-8): neo-classical free energy with "
                         "step-length anisotropy, Frank elasticity, active stress and a director field "
                         "(see [body.director]).");
  t.specs = {
      ParamSpec::real("mu", "Pa").greater_than(0).mark_required().help("Shear modulus mu (Eq. 2)."),
      ParamSpec::real("bulk", "Pa").greater_than(0).mark_required()
          .help("Penalty bulk modulus K that replaces the pressure p of Eq. 3 (p = -K ln J / J). "
                "No default: it must be chosen relative to mu (100 to 1000 mu is nearly incompressible)."),
      ParamSpec::real("s", "-").greater_than(0).at_most(100).defaults(2.0)
          .help("Step-length anisotropy s = l_parallel / l_perpendicular (Eq. 2); 1 = isotropic."),
      ParamSpec::real("kappa", "N").at_least(0).defaults(0.0).help("Frank modulus kappa (Eq. 2)."),
      ParamSpec::real("mobility", "1/(Pa s)").at_least(0).defaults(0.0)
          .help("Allen-Cahn mobility L of the director relaxation (Eq. 5-6); 0 = the director follows the body rotation only."),
      ParamSpec::real("zeta", "Pa").defaults(0.0)
          .help("Activity zeta of the active stress -zeta h x h (Eq. 1). zeta < 0 contracts the material "
                "along h (contractile), zeta > 0 elongates it (extensile)."),
      ParamSpec::choice("zeta_profile", {"uniform", "axial", "equatorial", "radial"}).defaults(std::string("uniform"))
          .help("Spatial profile of the activity, with c = h0 . a the cosine between the reference director and "
                "a = zeta_axis: uniform = zeta everywhere; axial = zeta |c|^p, full activity where h0 is along the "
                "axis (a cell's flat faces), none where it is perpendicular (its rim); equatorial = zeta "
                "(1 - c^2)^(p/2), the complement: active at the rim, passive in the faces; radial = zeta (1 - rho^2)^p, "
                "rho = distance of X from the axis through the centroid over the largest such distance: full "
                "activity at the centre of a cell's faces, none at its rim (p = zeta_power)."),
      ParamSpec::real("zeta_power", "-").at_least(0.5).at_most(64).defaults(2.0)
          .help("Exponent p of the axial / equatorial activity profile; larger p confines the activity to "
                "where h0 is closer to (axial) or further from (equatorial) the axis."),
      ParamSpec::choice("zeta_layer", {"all", "inner", "outer", "bending"}).defaults(std::string("all"))
          .help("Through-the-wall profile of the activity in a shell: all = the whole wall; inner / outer = "
                "only the half of the wall nearer that surface, which bends the wall like a bimetal strip; "
                "bending = zeta in the inner half and -zeta in the outer half, a pure bending moment "
                "(spontaneous curvature) with no net change of the wall's area."),
      ParamSpec::real("zeta_rim", "Pa").defaults(0.0)
          .help("Activity added at a cell's rim, through the whole wall: zeta_rim |s|^q with s the sine of the "
                "angle between h0 and zeta_axis (1 where the wall normal is perpendicular to the axis) and "
                "q = zeta_rim_power, through the part of the wall that zeta_rim_layer names. zeta_rim > 0 "
                "(extensile along the wall normal) shrinks the rim in-plane."),
      ParamSpec::real("zeta_rim_power", "-").at_least(0.5).at_most(64).defaults(2.0)
          .help("Exponent q of the rim activity profile |s|^q; larger q confines it to a narrower band."),
      ParamSpec::choice("zeta_rim_layer", {"all", "inner", "outer", "bending"}).defaults(std::string("all"))
          .help("Through-the-wall profile of the rim activity, as zeta_layer is for zeta."),
      ParamSpec::vec3("zeta_axis", "-").defaults(Vec3(0.0, 0.0, 1.0))
          .help("Axis a of the axial activity profile (normalised; must be non-zero)."),
  };
  return t;
}

}  // namespace

std::vector<ParamTable> materials() { return {lce(), mooney_rivlin()}; }

}  // namespace rkpm::scene::tables
