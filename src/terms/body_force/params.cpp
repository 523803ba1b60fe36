#include "terms/body_force/settings.hpp"
#include "terms/catalog.hpp"

namespace rkpm::terms::body_force {

using scene::ParamSpec;
using scene::Reference;
using sim::BodyForceSettings;

const scene::SettingsTable<BodyForceSettings>& settings_table() {
  static const auto table =
      scene::SettingsTable<BodyForceSettings>(
          term_table("body_force", "Uniform acceleration field (gravity): force rho0 g V on every particle."))
          .bind(&BodyForceSettings::body, ParamSpec::text("body").mark_required().refers_to(Reference::body)
                                     .help("The body it acts on."))
          .bind(&BodyForceSettings::acceleration,
                ParamSpec::vec3("acceleration", "m/s^2").at_least(-1e15).at_most(1e15).mark_required()
                  .help("Acceleration g. Each component within 1e15 m/s^2 (10^14 g), so that the forces and "
                        "the relaxation's residual stay finite."));
  return table;
}

scene::ParamTable table() { return settings_table().table(); }

}  // namespace rkpm::terms::body_force
