// The [body.material] table of model = "neo_hookean" (compiled into rkpm_scene).
#include "materials/catalog.hpp"
#include "materials/neo_hookean/settings.hpp"

namespace rkpm::materials::neo_hookean {

using scene::ParamSpec;

const scene::SettingsTable<Settings>& settings_table() {
  static const auto table =
      scene::SettingsTable<Settings>(
          material_table("neo_hookean",
                         "Compressible neo-Hookean solid with Lame constants mu and lambda: "
                         "W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2. Small strain: shear modulus mu, "
                         "bulk modulus lambda + 2 mu/3."))
          .bind(&Settings::mu, ParamSpec::real("mu", "Pa").greater_than(0).mark_required()
                                   .help("Shear modulus mu (Lame's second parameter)."))
          .bind(&Settings::lambda,
                ParamSpec::real("lambda", "Pa").greater_than(0).mark_required()
                    .help("Lame's first parameter lambda; the small-strain bulk modulus is lambda + 2 mu/3 "
                          "(lambda >> mu is nearly incompressible)."));
  return table;
}

scene::ParamTable table() { return settings_table().table(); }

}  // namespace rkpm::materials::neo_hookean
