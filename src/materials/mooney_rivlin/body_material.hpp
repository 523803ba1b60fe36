// What a Mooney-Rivlin body holds: the parameters of every integration point (uniform,
// or graded along an axis by seed Eq. 18), and the interface of sim::Material. It
// carries no per-point state.
#pragma once

#include "materials/mooney_rivlin/mooney_rivlin.hpp"
#include "materials/state_hooks.hpp"
#include "rkpm/common/types.hpp"

#include <cstddef>
#include <vector>

namespace rkpm::materials::mooney_rivlin {

struct BodyMaterial : Stateless {
  std::vector<MooneyRivlin> at_point;  // Eq. 9-11 parameters per integration point

  Mat3 stress(Index L, const Mat3& F) const { return at_point[L].first_piola(F); }  // P = dW/dF (Eq. 11)
  double energy(Index L, const Mat3& F) const { return at_point[L].energy(F); }
  double wave_speed(Index L, const Mat3& F, double rho0) const { return at_point[L].wave_speed(F, rho0); }
  double shear_modulus(Index L) const { return at_point[static_cast<std::size_t>(L)].shear_modulus(); }
  std::size_t state_bytes() const { return at_point.size() * sizeof(MooneyRivlin); }
};

}  // namespace rkpm::materials::mooney_rivlin
