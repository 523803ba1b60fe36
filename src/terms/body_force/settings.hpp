// Settings of the body_force term, read from its [[term]] table (params.cpp).
#pragma once

#include "rkpm/common/types.hpp"
#include "rkpm/scene/settings_table.hpp"

#include <string>

namespace rkpm::sim {

struct BodyForceSettings {
  std::string body;                     // the body it acts on
  Vec3 acceleration = Vec3::Zero();     // g [m/s^2]
};

}  // namespace rkpm::sim

namespace rkpm::terms::body_force {
const scene::SettingsTable<sim::BodyForceSettings>& settings_table();

}  // namespace rkpm::terms::body_force
