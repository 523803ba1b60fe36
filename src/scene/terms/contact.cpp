#include "terms/terms.hpp"

#include "rkpm/scene/param_set.hpp"

#include <fmt/format.h>

namespace rkpm::scene::terms {

// Derived defaults are filled here so that code reading the scene sees numbers.
static void finish_contact(ParamSet& p) {
  const double s0 = p.real("s0");
  if (!p.has("cutoff")) p.set("cutoff", 3.0 * s0, p.table_line(), false);
  if (!p.has("skin")) p.set("skin", 0.5 * s0, p.table_line(), false);
  if (p.real("cutoff") <= s0) {
    throw p.error("cutoff", fmt::format("a cutoff larger than s0 = {} m (the potential's minimum)",
                                        format_value(s0)));
  }
}

ParamTable contact() {
  ParamTable t = term_table("contact",
                            "Coarse-grained adhesive contact between two bodies (CGCM, seed Eq. 13-14): "
                            "Lennard-Jones potential phi(r) = eps [(s0/r)^12 - 2 (s0/r)^6] integrated over "
                            "both volumes with particle densities beta.");
  t.specs = {
      ParamSpec::text_list("bodies").with_length(2).mark_required().refers_to(Reference::bodies)
          .help("The two interacting bodies (different)."),
      ParamSpec::real("epsilon", "J").greater_than(0).mark_required().help("Depth eps of the potential well (Eq. 13)."),
      ParamSpec::real_list("beta", "1/m^3").with_length(2).at_least(0).defaults(std::vector<double>{0.0, 0.0})
          .help("Densities beta1, beta2 of interacting molecules (Eq. 14), in the order of `bodies`; "
                "0 = the body's particle number density (particles / cloud volume)."),
      ParamSpec::real("s0", "m").greater_than(0).mark_required().help("Equilibrium distance sigma0 (Eq. 13)."),
      ParamSpec::real("cutoff", "m").greater_than(0).absent_means("3 s0")
          .help("Interaction cutoff radius; must exceed s0."),
      ParamSpec::real("skin", "m").at_least(0).absent_means("0.5 s0")
          .help("Verlet skin: pair lists are rebuilt when a particle has moved skin/2."),
  };
  t.finish = finish_contact;
  return t;
}

}  // namespace rkpm::scene::terms
