// Settings of the lce model, read from its [body.material] table (params.cpp).
#pragma once

#include "rkpm/common/types.hpp"
#include "rkpm/scene/settings_table.hpp"

#include <string>

namespace rkpm::materials::lce {

struct Settings {
  // The kernel's parameters (liquid_crystal_elastomer.hpp, Eq. 1-7).
  double mu = 0.0;        // [Pa]
  double bulk = 0.0;      // [Pa] K
  double s = 2.0;         // [-]
  double kappa = 0.0;     // [N]
  double mobility = 0.0;  // [1/(Pa s)]
  double zeta = 0.0;      // [Pa]
  // The spatial activity field (body_material_activity.cpp).
  std::string zeta_profile = "uniform";  // uniform, axial, equatorial or radial
  double zeta_power = 2.0;               // [-] p
  std::string zeta_layer = "all";        // all, inner, outer or bending
  double zeta_rim = 0.0;                 // [Pa]
  double zeta_rim_power = 2.0;           // [-] q
  std::string zeta_rim_layer = "all";    // all, inner, outer or bending
  double zeta_fold = 0.0;                // [Pa] a second, narrower band at the rim
  double zeta_fold_power = 16.0;         // [-]
  std::string zeta_fold_layer = "outer";  // all, inner, outer or bending
  double zeta_reference_thickness = 0.0; // [m] T_ref; 0 = layer profiles independent of the wall
  double zeta_rim_fold_share = 0.0;      // [-] f: share of zeta_rim that grows as (T / T_ref)^3
  Vec3 zeta_axis = Vec3::UnitZ();        // [-] a (not normalised)
};

const scene::SettingsTable<Settings>& settings_table();

}  // namespace rkpm::materials::lce
