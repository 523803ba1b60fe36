// The material's per-point state of a body, reached through the hooks every
// BodyMaterial has (materials/state_hooks.hpp; a stateless model's do nothing). Each
// function dispatches once per body over the material catalog. The integrator calls
// them in the order state_hooks.hpp lists; nothing here knows which model has what.
#pragma once

#include "rkpm/sim/body.hpp"

#include <string>
#include <vector>

namespace rkpm::sim {

class StateRecord;

// Whether the body's material carries per-point state (not materials::Stateless).
bool has_material_state(const Body& body);

// Once, after set-up (Integrator::initialize).
void prepare_material_state(Body& body, const materials::StateDemand& demand);
// Before the step moves the body.
void begin_state_step(Body& body);
// After the step's force pass (and FIRE), at fixed positions. Distributed: this rank's
// share of the ledger entries.
materials::StateUpdate end_state_step(Body& body, double dt);
// The material's non-conservative work along the motion from F_from (per point) to the
// current F (a FIRE 2.0 step back): this rank's share.
materials::StateUpdate state_work_since(const Body& body, const std::vector<Mat3>& F_from);
// The largest stable step of the state's own update at this rank's points (infinity:
// no limit).
double state_stable_dt(const Body& body);
// The state relaxes in time by itself.
bool state_evolves_in_time(const Body& body);
// Distance of the state from its own equilibrium at this rank's points (0 without state).
double state_residual(const Body& body);

// Checkpoint: the state under `prefix`, and back (throws StateError naming the field).
void save_material_state(const Body& body, StateRecord& record, const std::string& prefix);
void load_material_state(Body& body, const StateRecord& record, const std::string& prefix);

// The fields the material shows in frames, by their declared names.
std::vector<materials::OutputField> material_output_fields(const Body& body);

// Nested iteration: `to`'s state from `from`'s (the same scene on a coarser cloud).
void transfer_material_state(const Body& from, Body& to, const materials::VectorInterpolation& interpolate);

}  // namespace rkpm::sim
