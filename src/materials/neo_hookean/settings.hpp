// Settings of the neo_hookean model, read from its [body.material] table (params.cpp):
// the kernel's two Lame constants, bound directly.
#pragma once

#include "materials/neo_hookean/neo_hookean.hpp"
#include "rkpm/scene/settings_table.hpp"

namespace rkpm::materials::neo_hookean {

using Settings = NeoHookean;

const scene::SettingsTable<Settings>& settings_table();

}  // namespace rkpm::materials::neo_hookean
