// Settings of the surface_pressure term, read from its [[term]] table (params.cpp).
#pragma once

#include "rkpm/scene/settings_table.hpp"

#include <string>

namespace rkpm::sim {

// Follower pressure on a surface.
struct SurfacePressureSettings {
  std::string body;        // the loaded body
  std::string surface;     // the loaded surface, or "all"
  double pressure = 0.0;   // p [Pa]; > 0 pushes the surface inwards
};

}  // namespace rkpm::sim

namespace rkpm::terms::surface_pressure {
const scene::SettingsTable<sim::SurfacePressureSettings>& settings_table();
}  // namespace rkpm::terms::surface_pressure
