// What a neo-Hookean body holds: one parameter set for all its points, and the
// interface of sim::Material.
#pragma once

#include "materials/neo_hookean/neo_hookean.hpp"
#include "rkpm/common/types.hpp"
#include "rkpm/sim/director_field.hpp"

#include <cstddef>

namespace rkpm::materials::neo_hookean {

struct BodyMaterial {
  static constexpr bool needs_director = false;

  NeoHookean model;

  Mat3 first_piola(Index /*L*/, const Mat3& F, const Mat3& /*grad_h*/, Mat3* /*frank_flux*/,
                   const sim::DirectorField* /*director*/) const {
    return model.first_piola(F);
  }
  double energy(Index /*L*/, const Mat3& F, const sim::DirectorField* /*director*/) const {
    return model.energy(F);
  }
  double wave_speed(Index /*L*/, const Mat3& F, const sim::DirectorField* /*director*/, double rho0) const {
    return model.wave_speed(F, rho0);
  }
  double shear_modulus(Index /*L*/) const { return model.shear_modulus(); }
  std::size_t state_bytes() const { return 0; }
};

}  // namespace rkpm::materials::neo_hookean
