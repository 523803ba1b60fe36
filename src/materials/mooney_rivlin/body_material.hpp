// What a Mooney-Rivlin body holds: the parameters of every integration point (uniform,
// or graded along an axis by seed Eq. 18), and the interface of sim::Material.
#pragma once

#include "materials/mooney_rivlin/mooney_rivlin.hpp"
#include "rkpm/common/types.hpp"
#include "rkpm/sim/director_field.hpp"

#include <cstddef>
#include <vector>

namespace rkpm::materials::mooney_rivlin {

struct BodyMaterial {
  static constexpr bool needs_director = false;

  std::vector<MooneyRivlin> at_point;  // Eq. 9-11 parameters per integration point

  // P = dW/dF (Eq. 11); a Mooney-Rivlin point has no director and no Frank flux.
  Mat3 first_piola(Index L, const Mat3& F, const Mat3& /*grad_h*/, Mat3* /*frank_flux*/,
                   const sim::DirectorField* /*director*/) const {
    return at_point[L].first_piola(F);
  }
  double energy(Index L, const Mat3& F, const sim::DirectorField* /*director*/) const {
    return at_point[L].energy(F);
  }
  double wave_speed(Index L, const Mat3& F, const sim::DirectorField* /*director*/, double rho0) const {
    return at_point[L].wave_speed(F, rho0);
  }
  double shear_modulus(Index L) const { return at_point[static_cast<std::size_t>(L)].shear_modulus(); }
  std::size_t state_bytes() const { return at_point.size() * sizeof(MooneyRivlin); }
};

}  // namespace rkpm::materials::mooney_rivlin
