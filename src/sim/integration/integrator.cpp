// The integrator's stages (rkpm/sim/integrator.hpp): set-up, the step as its list of
// stages (kick, drift, forces, kick, FIRE, the materials' state), the Newton-Krylov
// finish and the checkpointed state. Its step size, ledger and checks have files of
// their own (integrator_step_size.cpp, integrator_ledger.cpp, integrator_checks.cpp).
#include "rkpm/sim/integrator.hpp"

#include "rkpm/sim/body_state.hpp"
#include "rkpm/sim/stable_step.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rkpm::sim {

namespace {

// The integration weights' sum: this rank's rows (a distributed run's other rows are
// empty, weight 0), summed over the ranks.
double body_volume(const World& world, const Body& body) {
  double v = 0.0;
  for (Index L = body.owned_begin(); L < body.owned_end(); ++L) v += body.gradient.weight[L];
  return world.comm->sum(v);
}

}  // namespace

Integrator::Integrator(World& world, IntegratorSettings settings)
    : world_(world), settings_(settings), step_size_(settings_), fire_(settings.fire) {}

// Forces at the new positions (the bodies' internal forces, then every term's) and the
// essential boundary conditions by the transformation method (its reactions' power
// goes to the ledger). The accelerations are not stored: the kicks read f / inertia
// (acceleration()), the same bits at a third of the memory traffic of an array.
void Integrator::evaluate_forces() {
  compute_forces(world_);
  ++force_evaluations_;
  support_power_ = 0.0;
  for (auto& bp : world_.bodies) support_power_ += bp->constraints.transform_forces(bp->force);
  term_power_ = power_of_terms();
}

void Integrator::initialize() {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (auto& bp : world_.bodies) {
    Body& b = *bp;
    b.constraints.impose(b.d, b.v);
    for (Index i = b.owned_begin(); i < b.owned_end(); ++i) {
      lo = lo.cwiseMin(nodal_position(b, i));
      hi = hi.cwiseMax(nodal_position(b, i));
    }
  }
  for (int c = 0; c < 3; ++c) {
    lo[c] = world_.comm->min(lo[c]);
    hi[c] = world_.comm->max(hi[c]);
  }
  centre_ = 0.5 * (lo + hi);
  if (settings_.domain_size <= 0.0) settings_.domain_size = 50.0 * (hi - lo).norm();

  for (auto& bp : world_.bodies) {
    bp->inertia = bp->mass;
    prepare_material_state(*bp, {settings_.relax_state_tol > 0.0, bp->distributed()});
    plan_force_scatter(*bp);  // the state decides whether a coupled flux is scattered too
  }
  evaluate_forces();
  unscaled_stable_dt_ = estimate_stable_dt();
  if (settings_.mode == Mode::Relax && settings_.mass_scaling) {
    scale_masses();  // the forces do not depend on the masses; the accelerations follow
  }
  for (const auto& bp : world_.bodies)
    constraint_amplification_ = std::max(constraint_amplification_, bp->constraints.amplification());
  constraint_amplification_ = world_.comm->max(constraint_amplification_);
  if (settings_.stable_step_auto && constraint_amplification_ > kAmplifyingConstraints)
    settings_.measured_stable_step = true;
  if (settings_.measured_stable_step) calibrate_stable_step();
  scale_inertia_for_terms();
  step_size_.start(estimate_stable_dt());
  if (settings_.mode == Mode::Dynamic) motion_dt_ = motion_limited_dt();
  ledger_ = EnergyLedger{};
  ledger_.kinetic = kinetic_energy(world_);
  ledger_.initial = ledger_.kinetic + stored_energy();
  check_state();
  // The relaxation's scales, fixed for the run: each body's mean shear modulus, and
  // sum over bodies of mu V.
  body_shear_modulus_.clear();
  reference_energy_ = 0.0;
  for (const auto& bp : world_.bodies) {
    body_shear_modulus_.push_back(mean_shear_modulus(*bp));
    reference_energy_ += body_shear_modulus_.back() * body_volume(world_, *bp);
  }
  update_convergence(kinetic_energy(world_));
}

// One step of velocity Verlet (the central-difference scheme with lumped masses) with
// mass-proportional damping taken implicitly in the second half-kick, followed in the
// relaxation mode by FIRE, then the update of the materials' state at fixed positions
// (the hooks of materials/state_hooks.hpp, in their order); the ledger books the step's
// energies, the state is checked, and now and then the stable step is re-estimated.
void Integrator::step() {
  StepBook& book = book_;
  book.h = dt();
  if (book.h < step_size_.dt()) ++motion_limited_steps_;
  book.old_term_power = term_power_;
  book.damping_power = 0.0;
  book.fire_dissipated = 0.0;
  book.state_energy.clear();
  book.active_work = 0.0;

  for (auto& bp : world_.bodies) begin_state_step(*bp);
  first_kick_and_drift(book);
  evaluate_forces();
  second_kick(book.h);
  book.kinetic_of_motion = kinetic_energy(world_);
  if (settings_.mode == Mode::Relax) fire(book);
  advance_states(book);
  ledger(book);
  world_.time += book.h;
  ++world_.step;
  check(book.kinetic_of_motion);
  step_size_policy();
}

// Damping is for dynamic runs; a relaxation run is damped by FIRE alone.
double Integrator::damping() const { return settings_.mode == Mode::Dynamic ? settings_.damping : 0.0; }

// Velocity Verlet, first half: v_{n+1/2} = v_n + h/2 (a_n - c v_n), d_{n+1} = d_n + h v_{n+1/2};
// the damping term is explicit in this half (its power, at v_{n+1/2}, goes to the
// ledger) and implicit in the second. The supports move with the step.
void Integrator::first_kick_and_drift(StepBook& book) {
  const double h = book.h;
  const double c = damping();
  ExactSum damping_power;  // exact: see kinetic_energy (world.cpp)
  for (auto& bp : world_.bodies) {
    Body& b = *bp;
#pragma omp parallel for schedule(static) reduction(+ : damping_power)
    for (Index i = b.owned_begin(); i < b.owned_end(); ++i) {
      b.v[i] += 0.5 * h * (acceleration(b, i) - c * b.v[i]);
      damping_power.add(c * b.inertia[i] * b.v[i].squaredNorm());
      b.d[i] += h * b.v[i];
    }
    b.constraints.advance(h, b.d, b.v);
  }
  book.damping_power = world_.comm->sum(damping_power);
}

// Velocity Verlet, second half, damping implicit in it (unconditionally stable for any
// c): v_{n+1} = (v_{n+1/2} + h/2 a_{n+1}) / (1 + c h/2); the supports' velocities are
// re-imposed.
void Integrator::second_kick(double h) {
  const double c = damping();
  for (auto& bp : world_.bodies) {
    Body& b = *bp;
    const double factor = 1.0 / (1.0 + 0.5 * c * h);
#pragma omp parallel for schedule(static)
    for (Index i = b.owned_begin(); i < b.owned_end(); ++i) b.v[i] = factor * (b.v[i] + 0.5 * h * acceleration(b, i));
    b.constraints.impose(b.d, b.v);
  }
}

// Relaxation: FIRE (Bitzek et al. 2006) mixes or stops the step-end velocities and sets
// the next step, never above the stable step.
void Integrator::fire(StepBook& book) {
  const FireStep r = fire_.update(world_, step_size_.dt(), step_size_.ceiling());
  step_size_.take_fire_step(r.dt);
  book.fire_dissipated = r.dissipated;
  if (r.step_back) step_back(book);
}

// FIRE 2.0's inertia correction of an uphill step: the free coordinates go back by
// dt v / 2 (dt the shrunk step, as in Guenole et al. 2020, Algorithm 2), the velocities
// stop, the constrained coordinates follow their constraints, and the forces are
// evaluated at the new state. The ledger books the jump: the loads do the work W along
// it (the trapezoidal rule of their power with the jump as the velocity over a unit
// time), and what the stored energy does not gain of it is dissipated:
// external += W, dissipated += W + A - (stored after - stored before). A is a material's
// non-conservative work along the jump (the LCE's active stress, Eq. 1; it stores
// nothing): the state update books it with the step's motion (F - F_start includes the
// jump), so the jump's share is dissipated here, or the balance would be off by A at
// every step back.
void Integrator::step_back(StepBook& book) {
  const double stored_before = stored_energy();
  jump_.resize(world_.bodies.size());
  jump_F_.resize(world_.bodies.size());
  for (std::size_t k = 0; k < world_.bodies.size(); ++k) {
    Body& b = *world_.bodies[k];
    jump_[k] = b.d;  // the coordinates before the jump
    if (has_material_state(b)) jump_F_[k] = b.F;
#pragma omp parallel for schedule(static)
    for (Index i = b.owned_begin(); i < b.owned_end(); ++i) b.d[i] -= 0.5 * step_size_.dt() * b.v[i];
  }
  stop_bodies(world_);  // the constrained coordinates follow the free ones
  // The jump as the velocity, for the loads' power along it.
  for (std::size_t k = 0; k < world_.bodies.size(); ++k) {
    Body& b = *world_.bodies[k];
#pragma omp parallel for schedule(static)
    for (Index i = b.owned_begin(); i < b.owned_end(); ++i) b.v[i] = b.d[i] - jump_[k][i];
  }
  const double power_before = power_of_terms();
  evaluate_forces();
  const double power_after = power_of_terms();
  stop_bodies(world_);
  const double work = 0.5 * (power_before + power_after);
  double active = 0.0;
  for (std::size_t k = 0; k < world_.bodies.size(); ++k)
    if (has_material_state(*world_.bodies[k]))
      active += world_.comm->sum(state_work_since(*world_.bodies[k], jump_F_[k]).active_work);
  ledger_.external += work;
  book.fire_dissipated += work + active - (stored_energy() - stored_before);
  ++step_backs_;
}

NewtonKrylovReport Integrator::finish_newton_krylov(const NewtonKrylovSettings& newton,
                                                    const std::function<void(const NewtonKrylovReport&)>& stepped) {
  if (world_.comm->parallel()) throw std::invalid_argument("the Newton-Krylov finish runs on one process");
  for (const auto& b : world_.bodies)
    if (state_evolves_in_time(*b))
      throw std::invalid_argument("the Newton-Krylov finish needs material states that do not relax in time by "
                                  "themselves (an LCE's mobility = 0); body '" + b->name + "' has one that does");
  // The solve starts from rest: what FIRE's velocities still hold is dissipated.
  ledger_.dissipated += kinetic_energy(world_);
  double stored_before = 0.0;
  std::vector<StateRecord> base_state(world_.bodies.size());
  double active = 0.0, state_change = 0.0;  // of the last follow
  NewtonKrylovHooks hooks;
  hooks.residual = [&] {
    update_convergence(0.0);
    return residual_;
  };
  hooks.hold = [&] {
    stored_before = stored_energy();
    for (std::size_t k = 0; k < world_.bodies.size(); ++k)
      if (Body& b = *world_.bodies[k]; has_material_state(b)) {
        update_deformation_gradients(b);  // the step's start from the same sums as every F `follow` makes
        begin_state_step(b);
        base_state[k] = StateRecord{};
        save_material_state(b, base_state[k], "");
      }
  };
  hooks.follow = [&] {
    // The state from the base state to the evaluated coordinates, as a step's motion
    // carries it; a state that does not relax in time by itself (checked above) depends
    // on the motion alone, so the unit pseudo-time cancels (the LCE's Eq. 7 co-rotation:
    // rate (F - F_start) / dt times dt).
    active = state_change = 0.0;
    for (std::size_t k = 0; k < world_.bodies.size(); ++k)
      if (Body& b = *world_.bodies[k]; has_material_state(b)) {
        update_deformation_gradients(b);
        load_material_state(b, base_state[k], "");
        const materials::StateUpdate d = end_state_step(b, 1.0);
        active += world_.comm->sum(d.active_work);
        state_change += state_energy_change(d);
      }
  };
  hooks.carry = [&](const std::vector<std::vector<Vec3>>& from) {
    // The loads' work along the update, with the update as the velocity over a unit time
    // (exact for dead loads).
    for (std::size_t k = 0; k < world_.bodies.size(); ++k) {
      Body& b = *world_.bodies[k];
      for (std::size_t i = 0; i < b.size(); ++i) b.v[i] = b.d[i] - from[k][i];
    }
    const double work = power_of_terms();
    stop_bodies(world_);
    ledger_.external += work;
    ledger_.active += active;
    ledger_.state += state_change;
    ledger_.dissipated += work + active + state_change - (stored_energy() - stored_before);
    check_state();
  };
  hooks.stepped = stepped;
  const NewtonKrylovReport report = solve_static_equilibrium(world_, body_shear_modulus_, newton, hooks);
  force_evaluations_ += report.force_evaluations;
  term_power_ = power_of_terms();
  kinetic_measure_ = 0.0;
  return report;
}

// Each body's material state moves at fixed positions (the LCE's, Eq. 5-8):
// the non-conservative work of the step's motion and the stored energy the update
// changes, booked apart.
void Integrator::advance_states(StepBook& book) {
  for (auto& bp : world_.bodies)
    if (has_material_state(*bp)) {
      const materials::StateUpdate d = end_state_step(*bp, book.h);
      book.active_work += world_.comm->sum(d.active_work);
      book.state_energy.push_back(state_energy_change(d));
    }
}

StateRecord Integrator::save_state() const {
  StateRecord s;
  step_size_.save(s);
  s.put_real("ledger.external", ledger_.external);
  s.put_real("ledger.active", ledger_.active);
  s.put_real("ledger.dissipated", ledger_.dissipated);
  s.put_real("ledger.initial", ledger_.initial);
  s.put_real("ledger.state", ledger_.state);
  s.put_real("term_power", term_power_);
  s.put_real("support_power", support_power_);
  s.put_real("fire.alpha", fire_.alpha());
  s.put_integer("fire.positive_steps", fire_.positive_steps());
  s.put_real("domain_size", settings_.domain_size);
  s.put_real("stable_step.calibration", calibration_);
  s.put_real("motion_dt", motion_dt_);
  s.put_integer("motion_limited_steps", motion_limited_steps_);
  s.put_integer("fire.step_backs", step_backs_);
  s.put_integer("force_evaluations", force_evaluations_);
  s.put_integer("stable_step.calibrations", calibrations_);
  s.put_vectors("centre", {centre_});
  return s;
}

void Integrator::load_state(const StateRecord& s) {
  step_size_.load(s);
  ledger_.external = s.real("ledger.external");
  ledger_.active = s.real("ledger.active");
  ledger_.dissipated = s.real("ledger.dissipated");
  ledger_.initial = s.real("ledger.initial");
  ledger_.state = s.real("ledger.state");
  term_power_ = s.real("term_power");
  support_power_ = s.real("support_power");
  fire_ = Fire(settings_.fire, s.real("fire.alpha"), s.integer("fire.positive_steps"));
  settings_.domain_size = s.real("domain_size");
  calibration_ = s.real("stable_step.calibration");
  motion_dt_ = s.real("motion_dt");
  motion_limited_steps_ = s.integer("motion_limited_steps");
  // Absent from checkpoints written before FIRE 2.0 existed (their runs had none).
  step_backs_ = s.has("fire.step_backs") ? s.integer("fire.step_backs") : 0;
  force_evaluations_ = s.integer("force_evaluations");
  calibrations_ = s.integer("stable_step.calibrations");
  centre_ = s.vectors("centre", 1).front();
}

}  // namespace rkpm::sim
