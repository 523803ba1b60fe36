#include "terms/terms.hpp"

namespace rkpm::scene::terms {

ParamTable volume_constraint() {
  ParamTable t = term_table("volume_constraint",
                            "Fluid enclosed by a closed surface (e.g. a cell's cytoplasm): its pressure "
                            "p = bulk ln(target V0 / V) acts on the surface, pushing outwards while the "
                            "enclosed volume V is below target V0.");
  t.specs = {
      ParamSpec::text("body").mark_required().refers_to(Reference::body).help("The body whose surface encloses the fluid."),
      ParamSpec::text("surface").mark_required().refers_to(Reference::surface)
          .help("The closed surface enclosing the volume (shell: \"inner\")."),
      ParamSpec::real("bulk", "Pa").greater_than(0).mark_required().help("Penalty bulk modulus of the enclosed fluid."),
      ParamSpec::real("target", "-").greater_than(0).defaults(1.0).help("Target volume / initial enclosed volume V0."),
  };
  return t;
}

}  // namespace rkpm::scene::terms
