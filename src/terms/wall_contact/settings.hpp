// Settings of the wall_contact term, read from its [[term]] table (params.cpp).
#pragma once

#include "rkpm/scene/settings_table.hpp"

#include <string>

namespace rkpm::sim {

struct WallContactSettings {
  std::string body;        // the body whose walls must not cross
  std::string surface;     // a named surface of the body
  double distance = 0.0;   // s0 [m]
  double pressure = 0.0;   // p0 [Pa]
  double exclusion = 0.0;  // reference distance below which pairs do not interact [m]; > s0
  double skin = 0.0;       // Verlet skin [m]
};

}  // namespace rkpm::sim

namespace rkpm::terms::wall_contact {
const scene::SettingsTable<sim::WallContactSettings>& settings_table();
}  // namespace rkpm::terms::wall_contact
