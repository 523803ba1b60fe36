// Settings of the volume_constraint term, read from its [[term]] table (params.cpp).
#pragma once

#include "rkpm/scene/settings_table.hpp"

#include <string>

namespace rkpm::sim {

// Fluid enclosed by a closed surface, held near a target volume by a penalty pressure.
struct VolumeConstraintSettings {
  std::string body;        // the body whose surface encloses the fluid
  std::string surface;     // the closed surface, or "all"
  double bulk = 0.0;       // penalty bulk modulus of the enclosed fluid [Pa]
  double target = 1.0;     // target volume / initial enclosed volume
};

}  // namespace rkpm::sim

namespace rkpm::terms::volume_constraint {
const scene::SettingsTable<sim::VolumeConstraintSettings>& settings_table();
}  // namespace rkpm::terms::volume_constraint
