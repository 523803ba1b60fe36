// Settings of the surface_tension term, read from its [[term]] table (params.cpp).
#pragma once

#include "rkpm/scene/settings_table.hpp"

#include <string>

namespace rkpm::sim {

// Isotropic surface tension gamma on a surface of a body (seed Eq. 15-17).
struct SurfaceTensionSettings {
  std::string body;        // the body
  std::string surface;     // the surface carrying the tension, or "all"
  double gamma = 0.0;      // [N/m]
};

}  // namespace rkpm::sim

namespace rkpm::terms::surface_tension {
const scene::SettingsTable<sim::SurfaceTensionSettings>& settings_table();
}  // namespace rkpm::terms::surface_tension
