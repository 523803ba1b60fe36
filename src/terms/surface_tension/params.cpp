#include "terms/catalog.hpp"
#include "terms/surface_tension/settings.hpp"

namespace rkpm::terms::surface_tension {

using scene::ParamSpec;
using scene::Reference;
using sim::SurfaceTensionSettings;

const scene::SettingsTable<SurfaceTensionSettings>& settings_table() {
  static const auto table =
      scene::SettingsTable<SurfaceTensionSettings>(
          term_table("surface_tension",
                     "Isotropic surface tension gamma on a surface (the MDWM surface stress, seed Eq. 17): "
                     "energy gamma * current area."))
          .bind(&SurfaceTensionSettings::body,
                ParamSpec::text("body").mark_required().refers_to(Reference::body).help("The body."))
          .bind(&SurfaceTensionSettings::surface,
                ParamSpec::text("surface").defaults(std::string("all")).refers_to(Reference::surface)
                    .help("The surface carrying the tension, or \"all\"."))
          .bind(&SurfaceTensionSettings::gamma,
                ParamSpec::real("gamma", "N/m").at_least(0).mark_required().help("Surface tension gamma."));
  return table;
}

scene::ParamTable table() { return settings_table().table(); }

}  // namespace rkpm::terms::surface_tension
