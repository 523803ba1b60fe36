#include "terms/terms.hpp"

namespace rkpm::scene::terms {

ParamTable surface_tension() {
  ParamTable t = term_table("surface_tension",
                            "Isotropic surface tension gamma on a surface (the MDWM surface stress, seed Eq. 17): "
                            "energy gamma * current area.");
  t.specs = {
      ParamSpec::text("body").mark_required().refers_to(Reference::body).help("The body."),
      ParamSpec::text("surface").defaults(std::string("all")).refers_to(Reference::surface)
          .help("The surface carrying the tension, or \"all\"."),
      ParamSpec::real("gamma", "N/m").at_least(0).mark_required().help("Surface tension gamma."),
  };
  return t;
}

}  // namespace rkpm::scene::terms
