// What an active liquid-crystal-elastomer body holds (seed Eq. 1-8): the model, the
// activity of every point, and the director field, the material's per-point state.
// The interface of sim::Material, with the state hooks of materials/state_hooks.hpp
// that a director needs (defined in body_material_director.cpp).
#pragma once

#include "materials/lce/director_field.hpp"
#include "materials/lce/director_point.hpp"
#include "materials/lce/liquid_crystal_elastomer.hpp"
#include "materials/state_hooks.hpp"
#include "rkpm/common/types.hpp"

#include <cstddef>
#include <variant>
#include <vector>

namespace rkpm::materials::lce {

struct BodyMaterial {
  LiquidCrystalElastomer model;
  // Activity of each point relative to model.zeta (the activity field); empty = uniform.
  std::vector<double> activity;
  DirectorField director;

  double activity_at(Index L) const { return activity.empty() ? 1.0 : activity[L]; }

  // Passive + active P (Eq. 1-4) with the active part scaled by the point's activity,
  // at the director and Grad_X h the last force pass left (the gradient is gathered
  // with F: coupled_field).
  Mat3 stress(Index L, const Mat3& F) const {
    return model.first_piola(F, director_point(director, L), activity_at(L), nullptr);
  }
  // The same, and the Frank flux dW/d(Grad_X h), for a pass that tracks its divergence.
  Mat3 stress_and_flux(Index L, const Mat3& F, Mat3& flux) const {
    return model.first_piola(F, director_point(director, L), activity_at(L), &flux);
  }
  // Stored (passive) energy; the active stress stores none.
  double energy(Index L, const Mat3& F) const { return model.energy(F, director_point(director, L)); }
  double wave_speed(Index L, const Mat3& F, double rho0) const {
    return model.wave_speed(F, director_point(director, L), rho0);
  }
  double shear_modulus(Index /*L*/) const { return model.mu; }
  // The activity and the director arrays the body keeps (h, h0, rate, F_start, and
  // with the Frank term grad_h, its flux and divergence).
  std::size_t state_bytes() const;

  // The state hooks (materials/state_hooks.hpp), body_material_director.cpp.
  CoupledField coupled_field();
  void prepare(sim::Body& body, const StateDemand& demand);
  void begin_step(sim::Body& body);
  StateUpdate end_step(sim::Body& body, double dt);
  StateUpdate work_since(const sim::Body& body, const std::vector<Mat3>& F_from) const;
  double stable_dt(const sim::Body& body) const;
  bool evolves_in_time() const;
  double residual(const sim::Body& body) const;
  void save_state(sim::StateRecord& record, const std::string& prefix) const;
  void load_state(const sim::StateRecord& record, const std::string& prefix, const sim::Body& body);
  std::vector<OutputField> output_fields() const;
  void transfer_state(const BodyMaterial& from, const VectorInterpolation& interpolate);

  // Div_X of the Frank flux at every particle from the stored state (F, h, Grad_X h),
  // for a body whose pass does not track it; one process only.
  void frank_divergence(const sim::Body& body, std::vector<Vec3>& divergence) const;
};

// A body's LCE material, or null when its model is another (for tests and tools that
// look at the director of whatever body they are given).
template <class AnyBody>
BodyMaterial* material_of(AnyBody& body) {
  return std::get_if<BodyMaterial>(&body.material);
}
template <class AnyBody>
const BodyMaterial* material_of(const AnyBody& body) {
  return std::get_if<BodyMaterial>(&body.material);
}

}  // namespace rkpm::materials::lce
