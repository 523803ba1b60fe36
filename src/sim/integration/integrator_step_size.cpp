// The integrator's step: the stable step (wave speeds, the terms' limits, the measured
// calibration), mass scaling for relaxation, and the step-size policy of each mode.
#include "rkpm/sim/integrator.hpp"

#include "rkpm/sim/body_state.hpp"
#include "rkpm/sim/stable_step.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rkpm::sim {

// The smallest wave-speed step spacing / c over the bodies at the current state.
double Integrator::bodies_wave_dt() const {
  double dt = std::numeric_limits<double>::infinity();
  for (const auto& b : world_.bodies) dt = std::min(dt, material_stable_dt(*b));
  return world_.comm->min(dt);
}

// The bodies' wave-speed step times the calibration (1 unless the step is measured),
// each term's own limit, and the material states' (state_stable_dt): the calibration is
// measured on the bodies' material stiffness together with whatever the terms add at
// that state, but a term that stiffens later (a contact that closes) keeps the limit
// it states, and a state's first-order relaxation (the LCE's, Eq. 5) is not a
// vibration the calibration sees.
double Integrator::estimate_stable_dt() const {
  double dt = calibration_ * bodies_wave_dt();
  for (const auto& t : world_.terms) dt = std::min(dt, t->stable_dt(world_));
  double state_dt = std::numeric_limits<double>::infinity();
  for (const auto& b : world_.bodies) state_dt = std::min(state_dt, state_stable_dt(*b));
  return std::min(dt, world_.comm->min(state_dt));
}

// The measured stable step 2 / omega_max (stable_step.hpp) over the wave-speed step at
// the same state. The wave-speed step follows the state between calibrations (it
// tracks the stiffening of the material with F); the ratio carries what the wave speed
// misses: the discretisation's softer shortest modes, and the stiffness the terms add
// (a volume constraint states no limit of its own). A ratio below 1 is kept too: the
// measurement is then the safer bound. An iteration that finds no positive stiffness
// leaves the calibration as it was.
void Integrator::calibrate_stable_step() {
  const FrequencyEstimate f = largest_frequency(world_);
  ++calibrations_;
  force_evaluations_ += f.iterations + 2;  // and the state's own forces, before and after
  const double wave = bodies_wave_dt();
  if (f.omega_max > 0.0 && std::isfinite(wave)) calibration_ = 2.0 / f.omega_max / wave;
}

// contact_mass_scaling: a stiff contact would hold the whole relaxation at its own
// step (its Gershgorin bound); its particles get heavier instead, until its limit
// reaches about the bodies' own step. The equilibrium does not depend on the masses.
// The velocities are kept, so the kinetic energy grows with the inertia; the ledger
// books that growth as negative dissipation (FIRE, the run's one sink, removes it
// again), and its balance holds.
void Integrator::scale_inertia_for_terms() {
  if (settings_.mode != Mode::Relax || !settings_.contact_mass_scaling) return;
  const double bodies_dt = calibration_ * bodies_wave_dt();
  const double kinetic_before = kinetic_energy(world_);
  for (auto& t : world_.terms) t->scale_inertia_to(world_, bodies_dt);
  ledger_.dissipated -= kinetic_energy(world_) - kinetic_before;
}

// Mass scaling for relaxation: the target is the median of every particle's own wave step
// at the start, so at most half the particles get heavier and the step is no longer set
// by the few shortest edges (a shell's tightly curved rim, a cubed sphere's corners).
// The median of an even count is the upper middle value: deterministic, no averaging.
void Integrator::scale_masses() {
  std::vector<std::vector<double>> steps(world_.bodies.size());
  std::vector<double> all;
  for (std::size_t b = 0; b < steps.size(); ++b) {
    const Body& body = *world_.bodies[b];
    particle_wave_steps(body, steps[b]);
    // Distributed: a rank knows the steps of its own particles (it holds their F); every
    // rank gathers them all, so that the median and the inertia of every particle,
    // ghosts included, are those of one process.
    steps[b] = par::gather_owned(*world_.comm, steps[b], body.owned_begin(), body.owned_end());
    all.insert(all.end(), steps[b].begin(), steps[b].end());
  }
  if (all.empty()) return;
  const auto middle = all.begin() + static_cast<std::ptrdiff_t>(all.size() / 2);
  std::nth_element(all.begin(), middle, all.end());
  for (std::size_t b = 0; b < steps.size(); ++b) scale_inertia(*world_.bodies[b], *middle, steps[b]);
}

// The stable step follows the state (stiffening, contact): it is re-estimated every
// stable_step_interval steps (10 by default; 1 for releases from large strain,
// docs/verification/stability.md), and the mode's step follows it (StepSizePolicy).
void Integrator::step_size_policy() {
  if (settings_.mode == Mode::Dynamic) motion_dt_ = motion_limited_dt();
  if (world_.step % settings_.stable_step_interval != 0) return;
  // The first estimate at or after each multiple of kCalibrateEvery calibrates, whatever
  // the interval (with 10 exactly at the multiples).
  if (settings_.measured_stable_step && world_.step % kCalibrateEvery < settings_.stable_step_interval)
    calibrate_stable_step();
  scale_inertia_for_terms();
  step_size_.follow(estimate_stable_dt());
}

// A release from a large strain accelerates particles so hard that they cross their
// neighbours within one step at the stable step, which is a bound for small motions
// (docs/verification/stability.md). Per particle, the step of the displacement |v| dt + |a| dt^2 / 2
// = kappa h is the positive root 2 kappa h / (|v| + sqrt(|v|^2 + 2 |a| kappa h)); the
// smallest over the particles, evaluated every step, because the motion changes faster
// than the material's stiffness.
double Integrator::motion_limited_dt() const {
  double dt = std::numeric_limits<double>::infinity();
  for (const auto& bp : world_.bodies) {
    const Body& b = *bp;
#pragma omp parallel for schedule(static) reduction(min : dt)
    for (Index i = b.owned_begin(); i < b.owned_end(); ++i) {
      const double reach = kMotionFraction * b.spacing[i];
      const double v = b.v[i].norm(), a = acceleration(b, i).norm();
      const double speed = v + std::sqrt(v * v + 2.0 * a * reach);
      if (speed > 0.0) dt = std::min(dt, 2.0 * reach / speed);
    }
  }
  return world_.comm->min(dt);
}

// Dynamic runs take the policy's step or the motion limit, the smaller; a testing run
// that allows unstable steps keeps its step as given.
double Integrator::mode_step_limit() const {
  if (settings_.mode != Mode::Dynamic || settings_.allow_unstable_dt) return step_size_.dt();
  return std::min(step_size_.dt(), motion_dt_);
}

}  // namespace rkpm::sim
