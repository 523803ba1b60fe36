#pragma once
// The spatial activity field of an active LCE body (seed Eq. 1: sigma_a = -zeta h x h),
// built from the [body.material] keys zeta, zeta_profile, zeta_power, zeta_layer,
// zeta_axis, zeta_rim and zeta_rim_power.
#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/body.hpp"

#include <vector>

namespace rkpm::sim {

// Per-particle activity zeta_L relative to `reference_zeta` (set here to zeta, or to
// zeta_rim when zeta = 0); empty when the activity is uniform. `body` must have its
// cloud and director field. Throws SetupError naming the key for an inconsistent choice.
std::vector<double> activity_field(const scene::BodySpec& spec, const Body& body, double& reference_zeta);

}  // namespace rkpm::sim
