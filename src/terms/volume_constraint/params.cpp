#include "terms/catalog.hpp"
#include "terms/volume_constraint/settings.hpp"

namespace rkpm::terms::volume_constraint {

using scene::ParamSpec;
using scene::Reference;
using sim::VolumeConstraintSettings;

const scene::SettingsTable<VolumeConstraintSettings>& settings_table() {
  static const auto table =
      scene::SettingsTable<VolumeConstraintSettings>(
          term_table("volume_constraint",
                     "Fluid enclosed by a closed surface (e.g. a cell's cytoplasm): its pressure "
                     "p = bulk ln(target V0 / V) acts on the surface, pushing outwards while the "
                     "enclosed volume V is below target V0."))
          .bind(&VolumeConstraintSettings::body,
                ParamSpec::text("body").mark_required().refers_to(Reference::body)
                    .help("The body whose surface encloses the fluid."))
          .bind(&VolumeConstraintSettings::surface,
                ParamSpec::text("surface").mark_required().refers_to(Reference::surface)
                    .help("The closed surface enclosing the volume (shell: \"inner\")."))
          .bind(&VolumeConstraintSettings::bulk, ParamSpec::real("bulk", "Pa").greater_than(0).mark_required()
                                                      .help("Penalty bulk modulus of the enclosed fluid."))
          .bind(&VolumeConstraintSettings::target, ParamSpec::real("target", "-").greater_than(0).defaults(1.0)
                                                        .help("Target volume / initial enclosed volume V0."));
  return table;
}

scene::ParamTable table() { return settings_table().table(); }

}  // namespace rkpm::terms::volume_constraint
