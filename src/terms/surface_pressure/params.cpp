#include "terms/catalog.hpp"
#include "terms/surface_pressure/settings.hpp"

namespace rkpm::terms::surface_pressure {

using scene::ParamSpec;
using scene::Reference;
using sim::SurfacePressureSettings;

const scene::SettingsTable<SurfacePressureSettings>& settings_table() {
  static const auto table =
      scene::SettingsTable<SurfacePressureSettings>(
          term_table("surface_pressure",
                     "Pressure on a surface: traction -p n, n the current outward normal (follower load)."))
          .bind(&SurfacePressureSettings::body,
                ParamSpec::text("body").mark_required().refers_to(Reference::body).help("The loaded body."))
          .bind(&SurfacePressureSettings::surface,
                ParamSpec::text("surface").mark_required().refers_to(Reference::surface)
                    .help("The loaded surface of that body, or \"all\"."))
          .bind(&SurfacePressureSettings::pressure, ParamSpec::real("pressure", "Pa").mark_required()
                                                         .help("Pressure p; > 0 pushes the surface inwards."));
  return table;
}

scene::ParamTable table() { return settings_table().table(); }

}  // namespace rkpm::terms::surface_pressure
