// What a neo-Hookean body holds: one parameter set for all its points, and the
// interface of sim::Material. It carries no per-point state.
#pragma once

#include "materials/neo_hookean/neo_hookean.hpp"
#include "materials/state_hooks.hpp"
#include "rkpm/common/types.hpp"

#include <cstddef>

namespace rkpm::materials::neo_hookean {

struct BodyMaterial : Stateless {
  NeoHookean model;

  Mat3 stress(Index /*L*/, const Mat3& F) const { return model.first_piola(F); }
  double energy(Index /*L*/, const Mat3& F) const { return model.energy(F); }
  double wave_speed(Index /*L*/, const Mat3& F, double rho0) const { return model.wave_speed(F, rho0); }
  double shear_modulus(Index /*L*/) const { return model.shear_modulus(); }
  std::size_t state_bytes() const { return 0; }
};

}  // namespace rkpm::materials::neo_hookean
