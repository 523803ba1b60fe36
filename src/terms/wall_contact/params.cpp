#include "terms/catalog.hpp"
#include "terms/wall_contact/settings.hpp"

#include "rkpm/scene/param_set.hpp"

#include <fmt/format.h>

namespace rkpm::terms::wall_contact {

using scene::ParamSet;
using scene::ParamSpec;
using scene::Reference;
using scene::format_value;
using sim::WallContactSettings;

// Derived defaults are filled here so that code reading the scene sees numbers.
static void finish_wall_contact(ParamSet& p) {
  const double s0 = p.real("distance");
  if (!p.has("exclusion")) p.set("exclusion", 3.0 * s0, p.table_line(), false);
  if (!p.has("skin")) p.set("skin", 0.5 * s0, p.table_line(), false);
  if (p.real("exclusion") <= s0) {
    throw p.error("exclusion", fmt::format("an exclusion larger than distance = {} m (particles of one wall "
                                           "closer than the contact distance would repel at rest)",
                                           format_value(s0)));
  }
}

const scene::SettingsTable<WallContactSettings>& settings_table() {
  static const auto table =
      scene::SettingsTable<WallContactSettings>(
          term_table("wall_contact",
                     "Repulsive contact between the walls of one body (e.g. the two faces of a cell "
                     "meeting in a deep dimple): the repulsive part of the Lennard-Jones potential "
                     "(seed Eq. 13), cut at its minimum, between particles of a surface that are far "
                     "apart in the reference configuration. Flat walls at gap d < distance press with "
                     "2 pi pressure (d/s0) [(s0/d)^12 - 2 (s0/d)^6 + 1]."))
          .bind(&WallContactSettings::body, ParamSpec::text("body").mark_required().refers_to(Reference::body)
                                                .help("The body whose walls must not cross."))
          .bind(&WallContactSettings::surface,
                ParamSpec::text("surface").mark_required().refers_to(Reference::surface)
                    .help("The surface whose distant parts repel (shell: \"inner\", the faces of the cavity)."))
          .bind(&WallContactSettings::distance,
                ParamSpec::real("distance", "m").greater_than(0).mark_required()
                    .help("Contact distance s0: the walls repel below it, not beyond."))
          .bind(&WallContactSettings::pressure,
                ParamSpec::real("pressure", "Pa").greater_than(0).mark_required()
                    .help("Pressure scale p0 (4.4 p0 at 0.9 s0, 40 p0 at 0.8 s0)."))
          .bind(&WallContactSettings::exclusion,
                ParamSpec::real("exclusion", "m").greater_than(0).absent_means("3 distance")
                    .help("Particles closer than this in the reference configuration belong to the same wall and "
                          "do not interact; must exceed distance."))
          .bind(&WallContactSettings::skin,
                ParamSpec::real("skin", "m").at_least(0).absent_means("0.5 distance")
                    .help("Verlet skin: the pair list is rebuilt when a particle has moved skin/2."))
          .finish(finish_wall_contact);
  return table;
}

scene::ParamTable table() { return settings_table().table(); }

}  // namespace rkpm::terms::wall_contact
