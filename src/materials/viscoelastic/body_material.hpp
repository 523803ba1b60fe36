// What a viscoelastic body holds: the model (prony_neo_hookean.hpp) and its per-point
// state, each point's viscous strains (ViscousState), held fixed through the force pass
// and relaxed at fixed positions after it (end_step). The interface of sim::Material
// with the state hooks of materials/state_hooks.hpp (body_material_state.cpp).
#pragma once

#include "materials/state_hooks.hpp"
#include "materials/viscoelastic/prony_neo_hookean.hpp"
#include "rkpm/common/types.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace rkpm::materials::viscoelastic {

struct BodyMaterial {
  PronyNeoHookean model;
  std::vector<ViscousState> state;  // per integration point (= particle)

  Mat3 stress(Index L, const Mat3& F) const { return model.first_piola(F, state[L]); }
  // Stored energy: the equilibrium branch's and what the Maxwell branches hold.
  double energy(Index L, const Mat3& F) const { return model.energy(F, state[L]); }
  double wave_speed(Index L, const Mat3& F, double rho0) const { return model.wave_speed(F, state[L], rho0); }
  // The long-term modulus: the relaxation's scale and the stabilization's (a relaxed
  // body is held by the equilibrium branch alone).
  double shear_modulus(Index /*L*/) const { return model.shear_modulus(); }
  std::size_t state_bytes() const { return state.size() * sizeof(ViscousState); }

  // The state hooks (materials/state_hooks.hpp), body_material_state.cpp.
  CoupledField coupled_field() { return {}; }
  void prepare(sim::Body& /*body*/, const StateDemand& /*demand*/) {}
  void begin_step(sim::Body& /*body*/) {}
  StateUpdate end_step(sim::Body& body, double dt);
  StateUpdate work_since(const sim::Body& /*body*/, const std::vector<Mat3>& /*F_from*/) const { return {}; }
  // The update is the exact flow at fixed F (prony_neo_hookean.hpp, Eq. 4): no limit.
  double stable_dt(const sim::Body& body) const;
  bool evolves_in_time() const { return model.branch_count > 0; }
  double residual(const sim::Body& body) const;
  void save_state(sim::StateRecord& record, const std::string& prefix) const;
  void load_state(const sim::StateRecord& record, const std::string& prefix, const sim::Body& body);
  std::vector<OutputField> output_fields() const { return {}; }
  void transfer_state(const BodyMaterial& from, const VectorInterpolation& interpolate);
};

}  // namespace rkpm::materials::viscoelastic
