#include "terms/catalog.hpp"
#include "terms/contact/settings.hpp"

#include "rkpm/scene/param_set.hpp"

#include <fmt/format.h>

namespace rkpm::terms::contact {

using scene::ParamSet;
using scene::ParamSpec;
using scene::Reference;
using scene::format_value;
using sim::ContactSettings;
using sim::StiffnessLaw;

// Derived defaults are filled here so that code reading the scene sees numbers.
static void finish_contact(ParamSet& p) {
  const double s0 = p.real("s0");
  if (!p.has("cutoff")) p.set("cutoff", 3.0 * s0, p.table_line(), false);
  if (!p.has("skin")) p.set("skin", 0.5 * s0, p.table_line(), false);
  if (p.real("cutoff") <= s0) {
    throw p.error("cutoff", fmt::format("a cutoff larger than s0 = {} m (the potential's minimum)",
                                        format_value(s0)));
  }
  if (p.choice("stiffness_law") == "linear") {
    if (!p.has("substrate"))
      throw p.error("stiffness_law", "a `substrate` key naming the body whose stiffness sets eps (stiffness_law = \"linear\")");
    const auto& bodies = p.texts("bodies");
    if (p.text("substrate") != bodies[0] && p.text("substrate") != bodies[1])
      throw p.error("substrate", fmt::format("one of the two `bodies` (\"{}\" or \"{}\")", bodies[0], bodies[1]));
  }
}

const scene::SettingsTable<ContactSettings>& settings_table() {
  static const auto table =
      scene::SettingsTable<ContactSettings>(
          term_table("contact",
                     "Coarse-grained adhesive contact between two bodies (CGCM, seed Eq. 13-14): "
                     "Lennard-Jones potential phi(r) = eps [(s0/r)^12 - 2 (s0/r)^6] integrated over "
                     "both volumes with particle densities beta."))
          .bind(&ContactSettings::bodies, ParamSpec::text_list("bodies").with_length(2).mark_required()
                                              .refers_to(Reference::bodies)
                                              .help("The two interacting bodies (different)."))
          .bind(&ContactSettings::epsilon, ParamSpec::real("epsilon", "J").greater_than(0).mark_required()
                                               .help("Depth eps of the potential well (Eq. 13)."))
          .bind(&ContactSettings::beta,
                ParamSpec::real_list("beta", "1/m^3").with_length(2).at_least(0)
                    .defaults(std::vector<double>{0.0, 0.0})
                    .help("Densities beta1, beta2 of interacting molecules (Eq. 14), in the order of `bodies`; "
                          "0 = the body's particle number density (particles / cloud volume)."))
          .bind(&ContactSettings::s0, ParamSpec::real("s0", "m").greater_than(0).mark_required()
                                          .help("Equilibrium distance sigma0 (Eq. 13)."))
          .bind(&ContactSettings::cutoff, ParamSpec::real("cutoff", "m").greater_than(0).absent_means("3 s0")
                                              .help("Interaction cutoff radius; must exceed s0."))
          .bind(&ContactSettings::skin, ParamSpec::real("skin", "m").at_least(0).absent_means("0.5 s0")
                                            .help("Verlet skin: pair lists are rebuilt when a particle has moved skin/2."))
          .bind(&ContactSettings::law,
                ParamSpec::choice("stiffness_law", {"none", "linear"}).defaults(std::string("none"))
                    .help("How eps depends on the substrate's elasticity (seed section 3.1): \"none\" = uniform; "
                          "\"linear\" = eps_J = eps * mu(X_J) / mu_ref at each substrate particle J, mu the "
                          "small-strain shear modulus."),
                [](const std::string& law) { return law == "linear" ? StiffnessLaw::linear : StiffnessLaw::none; })
          .bind(&ContactSettings::substrate,
                ParamSpec::text("substrate").refers_to(Reference::body)
                    .absent_means("required when stiffness_law = \"linear\"")
                    .help("The body (one of `bodies`) whose local shear modulus scales eps."))
          .bind(&ContactSettings::stiffness_reference,
                ParamSpec::real("stiffness_reference", "Pa").at_least(0).defaults(0.0)
                    .help("mu_ref of the linear stiffness law; 0 = the volume-weighted mean shear modulus of the "
                          "substrate."))
          .bind(&ContactSettings::report_surface,
                ParamSpec::text("report_surface").defaults(std::string(""))
                    .help("A surface of the second body (e.g. \"zmax\" of a block substrate): adds to history.csv "
                          "and summary.json the first body's centroid, its smallest gap to that surface (negative = "
                          "interpenetration) and the contact radius. Empty = no report."))
          .bind(&ContactSettings::contact_gap,
                ParamSpec::real("contact_gap", "m").at_least(0).defaults(0.0)
                    .help("Report: particles of the first body closer than this to the surface form the contact "
                          "patch; 0 = s0."))
          .bind(&ContactSettings::formulation,
                ParamSpec::choice("formulation", {"pairs", "surface"}).defaults(std::string("pairs"))
                    .help("How Eq. 14's double volume integral is evaluated. pairs: the seed's nodal quadrature, a "
                          "sum over particle pairs of both bodies; its depth sum is coarse where the particle layers "
                          "are not much finer than s0 (docs/verification/adhesion.md). surface: the depth integrals "
                          "in closed form for locally flat surfaces (the traction law of two half-spaces), summed "
                          "over the first body's boundary particles at their gaps to the second body's surface "
                          "(Sauer & De Lorenzis 2013); one rank only (docs/theory/contact.md)."),
                [](const std::string& f) {
                  return f == "surface" ? sim::ContactFormulation::surface : sim::ContactFormulation::pairs;
                })
          .finish(finish_contact);
  return table;
}

scene::ParamTable table() { return settings_table().table(); }

}  // namespace rkpm::terms::contact
