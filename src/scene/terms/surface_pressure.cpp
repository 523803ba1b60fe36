#include "terms/terms.hpp"

namespace rkpm::scene::terms {

ParamTable surface_pressure() {
  ParamTable t = term_table("surface_pressure",
                            "Pressure on a surface: traction -p n, n the current outward normal (follower load).");
  t.specs = {
      ParamSpec::text("body").mark_required().refers_to(Reference::body).help("The loaded body."),
      ParamSpec::text("surface").mark_required().refers_to(Reference::surface)
          .help("The loaded surface of that body, or \"all\"."),
      ParamSpec::real("pressure", "Pa").mark_required().help("Pressure p; > 0 pushes the surface inwards."),
  };
  return t;
}

}  // namespace rkpm::scene::terms
