// Explicit time integration of a World: velocity Verlet (central difference) with
// lumped masses, optional mass-proportional damping, and a FIRE relaxation mode
// for equilibrium problems. Keeps the energy ledger and checks every step for
// blow-up. A step is a short list of named stages (see step()).
#pragma once

#include "rkpm/sim/fire.hpp"
#include "rkpm/sim/newton_krylov.hpp"
#include "rkpm/sim/state_record.hpp"
#include "rkpm/sim/step_size_policy.hpp"
#include "rkpm/sim/world.hpp"

#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace rkpm::sim {

enum class Mode { Dynamic, Relax };

struct IntegratorSettings {
  Mode mode = Mode::Dynamic;
  double dt = 0.0;               // 0: automatic; otherwise the requested step [s]
  double dt_safety = 0.5;        // fraction of the estimated stable step
  double damping = 0.0;          // mass-proportional damping coefficient [1/s]
  double relax_force_tol = 1e-6; // residual: max_I |f_I| / (mu_mean V_I^(2/3)), mu_mean = mean_shear_modulus(body)
  double relax_velocity_tol = 1e-8;  // kinetic energy / sum over bodies of mu_mean V_body
  double relax_state_tol = 0.0;      // state_residual bound; 0: the materials' state is not part of the stop
  FireParameters fire;           // relax only: the FIRE variant (fire.hpp)
  bool newton_krylov_finish = false;  // relax only: after FIRE's stop, Newton-Krylov to newton.force_tol
  NewtonKrylovSettings newton;        // its settings (newton_krylov.hpp)
  bool mass_scaling = false;     // relax only: scale_inertia to the median particle step (body.hpp)
  bool contact_mass_scaling = false;  // relax only: terms raise their particles' inertia to the bodies' step (Term::scale_inertia_to)
  bool measured_stable_step = false;  // the wave-speed step calibrated by the measured omega_max (stable_step.hpp)
  // stable_step = "auto": initialize() measures the step when a body's essential
  // boundary conditions amplify (EssentialBC::amplification() above kAmplifyingConstraints).
  bool stable_step_auto = false;
  std::int64_t stable_step_interval = 10;  // steps between two estimates of the stable step
  bool allow_unstable_dt = false;    // testing only: keep a dt above the stable estimate
  double domain_size = 0.0;      // particles farther than this from the initial centre are runaway [m]
};

// Energy bookkeeping [J].
// Balance: kinetic + stored = initial + external + active + state - dissipated.
struct EnergyLedger {
  double kinetic = 0.0;
  double strain = 0.0;       // sum of the bodies' stored energy
  double interface = 0.0;    // energy stored by conservative terms (contact, surface, constraints)
  double external = 0.0;     // work done by loads and moving supports
  double active = 0.0;       // non-conservative work of the materials (the LCE's active stress, Eq. 1)
  double state = 0.0;        // stored energy changed by the materials' state updates at fixed F:
                             // negative where a state relaxes (the LCE's Allen-Cahn
                             // relaxation, Eq. 5; a viscous branch); the LCE's co-rotation
                             // (Eq. 7) and anchoring (Eq. 8) exchange energy either way
  double dissipated = 0.0;   // removed by damping and by FIRE velocity resets
  double initial = 0.0;      // kinetic + stored at the start

  double total() const { return kinetic + strain + interface; }
  // |total - (initial + external + active + state - dissipated)| relative to the largest energy involved.
  double relative_error() const;
};

// Raised when the state becomes unphysical. The message is the diagnosis: step,
// time, body, particle, position and the quantity that failed.
struct BlowUp : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Integrator {
 public:
  Integrator(World& world, IntegratorSettings settings);
  Integrator(const Integrator&) = delete;  // its step-size policy refers to its settings
  Integrator& operator=(const Integrator&) = delete;

  // Forces and accelerations at the initial state, the stable step and the ledger.
  void initialize();
  // One step; throws BlowUp (the world is then left at the failed state: callers
  // keep their last good output).
  void step();

  // The step the next step() takes: the policy's step, and in dynamic mode no longer
  // than the motion limit.
  double dt() const { return mode_step_limit(); }
  double stable_dt() const { return step_size_.stable_dt(); }
  // Recomputes the kinetic and stored energies at the current state and returns the ledger.
  const EnergyLedger& measure_energy();
  // Relaxation: the convergence measures after the last step.
  double residual() const { return residual_; }
  // The materials' states' distance from their own equilibrium (sim::state_residual), the
  // largest over the bodies and ranks, at the current state. Collective.
  double state_residual() const;
  // The same, measured after the last step when relax_state_tol > 0 (part of
  // converged() then); 0 otherwise.
  double state_measure() const { return state_measure_; }
  double kinetic_measure() const { return kinetic_measure_; }
  bool converged() const;
  // The step was clamped to the stable estimate (a warning for the user).
  bool dt_clamped() const { return step_size_.clamped(); }
  double min_J() const { return min_J_; }
  // The stable step at the start before mass scaling (= stable_dt() at the start without it).
  double unscaled_stable_dt() const { return unscaled_stable_dt_; }
  // measured_stable_step: the measured 2 / omega_max over the bodies' wave-speed step at
  // the last calibration (1 without the setting), and the calibrations made so far.
  double stable_step_calibration() const { return calibration_; }
  std::int64_t calibrations() const { return calibrations_; }
  // Whether the step is measured (stable_step = "measured", or "auto" with amplifying
  // constraints: known after initialize()).
  bool measures_stable_step() const { return settings_.measured_stable_step; }
  // The largest EssentialBC::amplification() over the bodies and ranks (after initialize()).
  double constraint_amplification() const { return constraint_amplification_; }
  // Above this, "auto" measures the step: a unit motion of the free coordinates moves
  // a constrained one by more than a unit (on a lattice it is about 0.1).
  static constexpr double kAmplifyingConstraints = 1.0;
  // Steps between two calibrations of a run that measures its stable step.
  static constexpr std::int64_t kCalibrateEvery = 1000;
  // Dynamic runs: no particle moves more than this fraction of its spacing in one step.
  static constexpr double kMotionFraction = 0.1;
  // The largest step over which no particle moves more than kMotionFraction of its
  // spacing at its present velocity and acceleration (infinite at rest).
  double motion_limited_dt() const;
  // Evaluations of every force so far (one per step, one at the start, and the stable
  // step's calibrations): the cost measure of the relaxation study, which wall time
  // on a shared machine is not.
  std::int64_t force_evaluations() const { return force_evaluations_; }
  // FIRE 2.0's uphill steps so far, each of which moved the positions back (step_back).
  std::int64_t step_backs() const { return step_backs_; }
  // Steps so far that the motion limit shortened.
  std::int64_t motion_limited_steps() const { return motion_limited_steps_; }

  // Relaxation's finish (`relax_finish = "newton_krylov"`): from the present state, Newton-
  // Krylov steps to a residual below settings.force_tol (newton_krylov.hpp). Each accepted
  // update carries the materials' state with it (end_state_step with a unit pseudo-time,
  // as a step's motion does: the LCE's Eq. 7 co-rotation and Eq. 8) and is booked in the ledger: the loads' work along it as their power at
  // the new state with the update as the velocity over a unit time (exact for dead
  // loads; one-sided, so second order in the update, for follower loads), the active
  // work, the state's energy change, and the rest of the stored energy's change as
  // dissipation; the kinetic energy FIRE leaves is dissipated at the start. Its force
  // evaluations count in force_evaluations(). One process, and states that do not relax
  // in time by themselves (an LCE with L = 0) only: std::invalid_argument otherwise.
  // `stepped` (optional) is called after each accepted Newton step (NewtonKrylovHooks).
  NewtonKrylovReport finish_newton_krylov(const NewtonKrylovSettings& settings,
                                          const std::function<void(const NewtonKrylovReport&)>& stepped = {});

  // Checkpointing: the integrator's own state as named fields (load_state throws
  // StateError naming a missing or mis-sized field).
  StateRecord save_state() const;
  void load_state(const StateRecord& state);

 private:
  // What the stages of one step hand to the ledger.
  struct StepBook {
    double h = 0.0;                             // the step taken [s]
    double old_term_power = 0.0;                // at the start of the step [W]
    double active_work = 0.0;                   // the materials' non-conservative work over the step [J]
    double damping_power = 0.0;                 // c sum_I m_I |v_I|^2 at the half step [W]
    double fire_dissipated = 0.0;               // kinetic energy removed by FIRE [J]
    double kinetic_of_motion = 0.0;             // kinetic energy after the second kick, before FIRE [J]
    std::vector<double> state_energy;           // per body with material state, in body order [J]
  };

  // The stages of step(), in order.
  void first_kick_and_drift(StepBook& book);
  void evaluate_forces();
  void second_kick(double h);
  void fire(StepBook& book);
  void step_back(StepBook& book);
  void advance_states(StepBook& book);
  double state_energy_change(const materials::StateUpdate& update) const;
  void ledger(const StepBook& book);
  void check(double kinetic_of_motion);  // throws BlowUp
  void step_size_policy();

  double estimate_stable_dt() const;
  double bodies_wave_dt() const;
  double mode_step_limit() const;
  void calibrate_stable_step();
  void scale_masses();
  void scale_inertia_for_terms();
  double damping() const;
  double stored_energy();
  double power_of_terms() const;
  void check_state();  // throws BlowUp
  void update_convergence(double kinetic_of_motion);

  World& world_;
  IntegratorSettings settings_;
  StepSizePolicy step_size_;  // refers to settings_, declared before it
  EnergyLedger ledger_;
  double term_power_ = 0.0, support_power_ = 0.0;
  double residual_ = 0.0, kinetic_measure_ = 0.0, state_measure_ = 0.0, min_J_ = 1.0;
  double energy_scale_ = 0.0;
  std::vector<double> body_shear_modulus_;  // mean_shear_modulus of each body (the residual's scale)
  double reference_energy_ = 0.0;           // sum over bodies of mu V (the kinetic measure's scale)
  double unscaled_stable_dt_ = 0.0;  // the stable step before mass scaling (for the report)
  double calibration_ = 1.0;         // applied to bodies_wave_dt() (measured_stable_step)
  double constraint_amplification_ = 0.0;
  double motion_dt_ = std::numeric_limits<double>::infinity();  // motion_limited_dt() after the last step
  std::int64_t motion_limited_steps_ = 0;
  std::int64_t force_evaluations_ = 0;
  std::int64_t calibrations_ = 0;
  Vec3 centre_ = Vec3::Zero();
  Fire fire_;  // relaxation mode only
  std::vector<std::vector<Vec3>> jump_;  // step_back's scratch: each body's coordinates before the jump
  std::vector<std::vector<Mat3>> jump_F_;  // and F of each body with material state (its active work)
  std::int64_t step_backs_ = 0;
  StepBook book_;
};

}  // namespace rkpm::sim
