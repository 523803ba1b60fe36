// The spatial activity field of an active LCE body (seed Eq. 1: sigma_a = -zeta h x h),
// from the activity settings of its [body.material] table: zeta, zeta_profile,
// zeta_power, zeta_layer, zeta_axis, zeta_rim, zeta_rim_power, zeta_rim_layer,
// zeta_fold, zeta_fold_power, zeta_fold_layer, zeta_reference_thickness and
// zeta_rim_fold_share.
#pragma once

#include "materials/lce/settings.hpp"
#include "rkpm/scene/param_set.hpp"
#include "rkpm/sim/body.hpp"

#include <vector>

namespace rkpm::materials::lce {

// Per-particle activity zeta_L relative to `reference_zeta` (set here to zeta, or to
// zeta_rim when zeta = 0); empty when the activity is uniform. `body` must have its
// cloud; `h0` is the reference director per particle. `table` is the [body.material] table the settings were read
// from, for the file and line of an error. `wall_thickness` is the shell generator's
// nominal wall thickness T (0 for other clouds), which zeta_reference_thickness and
// zeta_rim_fold_share scale by. Throws sim::SetupError naming the key for an inconsistent choice.
std::vector<double> activity_field(const Settings& settings, const scene::ParamSet& table, const sim::Body& body,
                                   const std::vector<Vec3>& h0, double wall_thickness, double& reference_zeta);

}  // namespace rkpm::materials::lce
