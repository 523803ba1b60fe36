// What an active liquid-crystal-elastomer body holds (seed Eq. 1-4): the model and the
// activity of every point; its director lives in Body::director. The interface of
// sim::Material.
#pragma once

#include "materials/lce/director_point.hpp"
#include "materials/lce/liquid_crystal_elastomer.hpp"
#include "rkpm/common/types.hpp"
#include "rkpm/sim/director_field.hpp"

#include <cstddef>
#include <vector>

namespace rkpm::materials::lce {

struct BodyMaterial {
  static constexpr bool needs_director = true;

  LiquidCrystalElastomer model;
  // Activity of each point relative to model.zeta (the activity field); empty = uniform.
  std::vector<double> activity;

  double activity_at(Index L) const { return activity.empty() ? 1.0 : activity[L]; }

  // Passive + active P (Eq. 1-4) with the active part scaled by the point's activity,
  // and the Frank flux dW/d(Grad_X h) when `frank_flux` is given.
  Mat3 first_piola(Index L, const Mat3& F, const Mat3& grad_h, Mat3* frank_flux,
                   const sim::DirectorField* director) const {
    return model.first_piola(F, director_point(*director, L, grad_h), activity_at(L), frank_flux);
  }
  // Stored (passive) energy; the active stress stores none.
  double energy(Index L, const Mat3& F, const sim::DirectorField* director) const {
    return model.energy(F, director_point(*director, L));
  }
  double wave_speed(Index L, const Mat3& F, const sim::DirectorField* director, double rho0) const {
    return model.wave_speed(F, director_point(*director, L), rho0);
  }
  double shear_modulus(Index /*L*/) const { return model.mu; }
  std::size_t state_bytes() const { return activity.size() * sizeof(double); }
};

}  // namespace rkpm::materials::lce
