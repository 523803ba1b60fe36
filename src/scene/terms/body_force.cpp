#include "terms/terms.hpp"

namespace rkpm::scene::terms {

ParamTable body_force() {
  ParamTable t = term_table("body_force", "Uniform acceleration field (gravity): force rho0 g V on every particle.");
  t.specs = {
      ParamSpec::text("body").mark_required().refers_to(Reference::body).help("The body it acts on."),
      ParamSpec::vec3("acceleration", "m/s^2").mark_required().help("Acceleration g."),
  };
  return t;
}

}  // namespace rkpm::scene::terms
