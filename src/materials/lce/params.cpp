// The [body.material] table of model = "lce" (compiled into rkpm_scene): the kernel's
// parameters and the activity field's. Its bodies take a [body.director] table.
#include "materials/catalog.hpp"
#include "materials/lce/settings.hpp"

namespace rkpm::materials::lce {

using scene::ParamSpec;

namespace {
// [body.director]: the LCE's own sub-table of [[body]] (Eq. 5-8), read by
// initial_director.
scene::ParamTable director_table() {
  scene::ParamTable t;
  t.section = "body.director";
  t.help = "Director field h of a liquid-crystal-elastomer body (seed Eq. 1-8). Only allowed "
           "when [body.material] model = \"lce\"; omitted, it takes these defaults.";
  t.specs = {
      ParamSpec::choice("initial", {"surface_normal", "radial", "fixed"}).defaults(std::string("surface_normal"))
          .help("Initial director h0: surface_normal = the outward normal of the nearest boundary "
                "particle; radial = away from the body's centroid; fixed = `vector` everywhere."),
      ParamSpec::vec3("vector", "-").defaults(Vec3(0, 0, 1))
          .help("The uniform initial director when initial = fixed (normalised; must be non-zero)."),
      ParamSpec::choice("boundary", {"normal", "free"}).defaults(std::string("normal"))
          .help("normal: h = h0 = n on the boundary (anchoring, Eq. 8). free: no anchoring."),
      ParamSpec::boolean("evolve").defaults(true)
          .help("Evolve h by the Allen-Cahn relaxation (Eq. 5-7) with the material's mobility."),
  };
  t.finish = [](scene::ParamSet& p) {
    const bool fixed = p.choice("initial") == "fixed";
    if (!fixed && p.given("vector")) throw p.error("vector", "no vector unless initial = \"fixed\"");
    // stableNorm: a vector of tiny or huge components is a direction too (the plain norm
    // squares them to 0 or infinity).
    if (fixed && p.vec3("vector").stableNorm() == 0.0) throw p.error("vector", "a non-zero vector");
  };
  return t;
}
}  // namespace

const scene::SettingsTable<Settings>& settings_table() {
  static const auto table =
      scene::SettingsTable<Settings>(
          material_table("lce",
                         "Active liquid-crystal elastomer (seed Eq. 1-8): neo-classical free energy with "
                         "step-length anisotropy, Frank elasticity, active stress and a director field "
                         "(see [body.director]).",
                         {director_table()}))
          .bind(&Settings::mu,
                ParamSpec::real("mu", "Pa").greater_than(0).mark_required().help("Shear modulus mu (Eq. 2)."))
          .bind(&Settings::bulk,
                ParamSpec::real("bulk", "Pa").greater_than(0).mark_required()
                  .help("Penalty bulk modulus K that replaces the pressure p of Eq. 3 (p = -K ln J / J). "
                        "No default: it must be chosen relative to mu (100 to 1000 mu is nearly incompressible)."))
          .bind(&Settings::s,
                ParamSpec::real("s", "-").at_least(0.01).at_most(100).defaults(2.0)
                  .help("Step-length anisotropy s = l_parallel / l_perpendicular (Eq. 2); 1 = isotropic. "
                        "Bounded on both sides alike: the stress carries 1/s, which overflows as s goes to 0."))
          .bind(&Settings::kappa,
                ParamSpec::real("kappa", "N").at_least(0).defaults(0.0).help("Frank modulus kappa (Eq. 2)."))
          .bind(&Settings::mobility,
                ParamSpec::real("mobility", "1/(Pa s)").at_least(0).defaults(0.0)
                  .help("Allen-Cahn mobility L of the director relaxation (Eq. 5-6); 0 = the director follows the body rotation only. "
                      "The step stays below 2 / (L times the director's stiffness), so a high L shortens it "
                      "(docs/verification/stability.md)."))
          .bind(&Settings::zeta,
                ParamSpec::real("zeta", "Pa").defaults(0.0)
                  .help("Activity zeta of the active stress -zeta h x h (Eq. 1). zeta < 0 contracts the material "
                        "along h (contractile), zeta > 0 elongates it (extensile)."))
          .bind(&Settings::zeta_profile,
                ParamSpec::choice("zeta_profile", {"uniform", "axial", "equatorial", "radial"}).defaults(std::string("uniform"))
                  .help("Spatial profile of the activity, with c = h0 . a the cosine between the reference director and "
                        "a = zeta_axis: uniform = zeta everywhere; axial = zeta |c|^p, full activity where h0 is along the "
                        "axis (a cell's flat faces), none where it is perpendicular (its rim); equatorial = zeta "
                        "(1 - c^2)^(p/2), the complement: active at the rim, passive in the faces; radial = zeta (1 - rho^2)^p, "
                        "rho = distance of X from the axis through the centroid over the largest such distance: full "
                        "activity at the centre of a cell's faces, none at its rim (p = zeta_power)."))
          .bind(&Settings::zeta_power,
                ParamSpec::real("zeta_power", "-").at_least(0.5).at_most(64).defaults(2.0)
                  .help("Exponent p of the axial / equatorial activity profile; larger p confines the activity to "
                        "where h0 is closer to (axial) or further from (equatorial) the axis."))
          .bind(&Settings::zeta_layer,
                ParamSpec::choice("zeta_layer", {"all", "inner", "outer", "bending"}).defaults(std::string("all"))
                  .help("Through-the-wall profile of the activity in a shell: all = the whole wall; inner / outer = "
                        "only the half of the wall nearer that surface, which bends the wall like a bimetal strip; "
                        "bending = zeta in the inner half and -zeta in the outer half, a pure bending moment "
                        "(spontaneous curvature) with no net change of the wall's area."))
          .bind(&Settings::zeta_rim,
                ParamSpec::real("zeta_rim", "Pa").defaults(0.0)
                  .help("Activity added at a cell's rim, through the whole wall: zeta_rim |s|^q with s the sine of the "
                        "angle between h0 and zeta_axis (1 where the wall normal is perpendicular to the axis) and "
                        "q = zeta_rim_power, through the part of the wall that zeta_rim_layer names. zeta_rim > 0 "
                        "(extensile along the wall normal) shrinks the rim in-plane."))
          .bind(&Settings::zeta_rim_power,
                ParamSpec::real("zeta_rim_power", "-").at_least(0.5).at_most(64).defaults(2.0)
                  .help("Exponent q of the rim activity profile |s|^q; larger q confines it to a narrower band."))
          .bind(&Settings::zeta_rim_layer,
                ParamSpec::choice("zeta_rim_layer", {"all", "inner", "outer", "bending"}).defaults(std::string("all"))
                  .help("Through-the-wall profile of the rim activity, as zeta_layer is for zeta."))
          .bind(&Settings::zeta_fold,
                ParamSpec::real("zeta_fold", "Pa").defaults(0.0)
                  .help("A second rim activity, in a narrower band at the equator: zeta_fold |s|^k with "
                        "k = zeta_fold_power, through the part of the wall that zeta_fold_layer names. With the "
                        "default layer (outer), zeta_fold < 0 (contractile along the wall normal) grows the outer "
                        "half of the wall in-plane there and opens a pointed equatorial fold into a rounder rim "
                        "(docs/verification/rbc.md, the ridge at the equator, measures -3e4 Pa on the RBC scene)."))
          .bind(&Settings::zeta_fold_power,
                ParamSpec::real("zeta_fold_power", "-").at_least(0.5).at_most(64).defaults(16.0)
                  .help("Exponent k of the fold activity profile |s|^k (16: within about 20 degrees of the equator)."))
          .bind(&Settings::zeta_fold_layer,
                ParamSpec::choice("zeta_fold_layer", {"all", "inner", "outer", "bending"}).defaults(std::string("outer"))
                  .help("Through-the-wall profile of the fold activity, as zeta_layer is for zeta."))
          .bind(&Settings::zeta_reference_thickness,
                ParamSpec::real("zeta_reference_thickness", "m").at_least(0).defaults(0.0)
                  .help("Wall thickness T_ref for which zeta and zeta_rim are given when their layer is inner, outer or "
                        "bending; 0 = use them as given at any thickness. When > 0, the part of a layer activity that "
                        "bends the wall (its difference between the two halves) is scaled by T / T_ref, T the shell "
                        "generator's thickness, and the part that changes the wall's area is kept: a bimetal wall bends "
                        "to curvature 3 de / (2 T) under a growth difference de between its halves, so the same shape "
                        "needs de proportional to T, while the in-plane growth does not depend on T."))
          .bind(&Settings::zeta_rim_fold_share,
                ParamSpec::real("zeta_rim_fold_share", "-").at_least(0).at_most(1).defaults(0.0)
                  .help("Share f of zeta_rim, as given at T_ref = zeta_reference_thickness, that grows with the "
                        "wall's bending stiffness (~T^3): zeta_rim is multiplied by (1 - f) + f (T / T_ref)^3, so a "
                        "thicker wall gets a stronger rim to hold its equatorial fold open and a thinner one a weaker "
                        "rim. 0 = zeta_rim at any thickness. Needs zeta_reference_thickness > 0. The default scene's "
                        "0.421 is fitted to the 0.75 um wall (docs/verification/rbc.md)."))
          .bind(&Settings::zeta_axis,
                ParamSpec::vec3("zeta_axis", "-").defaults(Vec3(0.0, 0.0, 1.0))
                  .help("Axis a of the axial activity profile (normalised; must be non-zero)."));
  return table;
}

scene::ParamTable table() { return settings_table().table(); }

}  // namespace rkpm::materials::lce
