// What a material may carry besides its parameters: per-point state that the step
// advances (the LCE's orientation field, Eq. 5-8; a viscoelastic material's internal
// variables), and the
// hooks through which the integrator, the checkpoint and the output reach it. A model
// whose BodyMaterial derives from `Stateless` has none of it and inherits hooks that do
// nothing; a stateful model overrides the ones it needs (by name: the calls are resolved
// at compile time through sim::Material's std::visit, not virtual).
//
// The order in which a step calls them (sim/integration/integrator.cpp):
//   begin_step          before the step moves the body (hold what the update measures from)
//   [kick, drift, force pass: stress(L, F) with the state held fixed]
//   [second kick; FIRE in a relaxation]
//   end_step(dt)        the state's update at fixed positions; returns its share of the
//                       energy ledger (StateUpdate)
// and, outside the step: prepare (once, after set-up), stable_dt (with the bodies' wave
// step), residual (the relaxation's stop), work_since (a FIRE 2.0 step back, a
// Newton-Krylov update), save_state / load_state (checkpoint, and the Newton-Krylov
// finish's base state), output_fields (frames) and transfer_state (nested iteration).
#pragma once

#include "rkpm/common/exact_sum.hpp"
#include "rkpm/common/types.hpp"

#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace rkpm::sim {
struct Body;
class StateRecord;
}  // namespace rkpm::sim

namespace rkpm::materials {

// The ledger's share of one state update (end_step, work_since) [J].
struct StateUpdate {
  double active_work = 0.0;    // non-conservative work the material did on the motion (the LCE's
                               // active stress, Eq. 1): -sum_L V_L int P_a : dF over the step
  // The stored energy the update changes at fixed F, as the exact sums before and after
  // it (this rank's points): the ranks' sums merge exactly (par::Comm::sum), so the
  // change has the same bits on any rank count. A relaxing state dissipates (after <
  // before); an imposed one (the LCE anchoring) may add.
  ExactSum energy_before, energy_after;
  double energy_change() const { return energy_after.value() - energy_before.value(); }
};

// A per-particle vector field whose reference gradient enters the stress (the LCE's
// orientation field, for the Frank term, Eq. 6): the force pass pulls its ghosts, gathers Grad_X of it
// with F in the same sweep of a row, and, when `flux` is set, scatters the weak
// divergence of the flux dW/d(Grad_X) in a second channel. Empty (`values` null) for a
// material without one.
struct CoupledField {
  std::vector<Vec3>* values = nullptr;      // per particle
  std::vector<Mat3>* gradient = nullptr;    // Grad_X per integration point (written by the pass)
  std::vector<Mat3>* flux = nullptr;        // dW/d(Grad_X) per point, or null: not tracked
  std::vector<Vec3>* divergence = nullptr;  // Div_X flux per particle (written when tracked)
  bool active() const { return values != nullptr; }
};

// A field a material shows in the output frames: `components` values per particle.
struct OutputField {
  std::string name;
  int components = 3;
  const double* values = nullptr;  // particle-major, components per particle
};

// Nested iteration's map of a per-particle Vec3 field from the coarser cloud's particles
// to the finer one's (the RK interpolation of the coarser body).
using VectorInterpolation = std::function<std::vector<Vec3>(const std::vector<Vec3>&)>;

// What the run asks of the state beyond the step (prepare).
struct StateDemand {
  bool residual_every_step = false;  // the relaxation's stop reads residual() every step
  bool distributed = false;          // the body is split over ranks
};

// The hooks of a material without per-point state.
struct Stateless {
  CoupledField coupled_field() { return {}; }
  void prepare(sim::Body& /*body*/, const StateDemand& /*demand*/) {}
  void begin_step(sim::Body& /*body*/) {}
  StateUpdate end_step(sim::Body& /*body*/, double /*dt*/) { return {}; }
  StateUpdate work_since(const sim::Body& /*body*/, const std::vector<Mat3>& /*F_from*/) const { return {}; }
  double stable_dt(const sim::Body& /*body*/) const { return std::numeric_limits<double>::infinity(); }
  // The state changes in time by itself (a relaxation with its own time scale): a solve
  // for static equilibrium that carries the state with the coordinates cannot hold it.
  bool evolves_in_time() const { return false; }
  // Distance of the state from its own equilibrium, dimensionless (0: no state).
  double residual(const sim::Body& /*body*/) const { return 0.0; }
  void save_state(sim::StateRecord& /*record*/, const std::string& /*prefix*/) const {}
  // Throws sim::StateError naming the field when the record's state is damaged.
  void load_state(const sim::StateRecord& /*record*/, const std::string& /*prefix*/, const sim::Body& /*body*/) {}
  std::vector<OutputField> output_fields() const { return {}; }
  // Nested iteration: the state of a body built on a finer cloud, from this body's
  // state on the coarser one; `interpolate` maps a per-particle Vec3 field of `from`
  // onto `to`'s particles (the RK interpolation).
  template <class Material>
  void transfer_state(const Material& /*from*/, const VectorInterpolation& /*interpolate*/) {}
};

}  // namespace rkpm::materials
