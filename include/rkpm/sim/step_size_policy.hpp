// The step each mode takes, given the stable step: the one place that decides between
// a user's step, the automatic step (dt_safety times the stable step) and FIRE's own.
// How the stable step is estimated (wave speeds, the terms' limits, the measured
// calibration) is the integrator's (integrator_step_size.cpp); this class only applies it.
//
// Three cases (docs/verification/stability.md):
//   - a user step (dt > 0) is kept while it stays at or below the stable step; once it
//     exceeds it, it is clamped to the automatic step and the run follows the automatic
//     step from then on (unless allow_unstable_dt, for tests);
//   - a dynamic run, or a clamped one, takes the automatic step;
//   - a relaxation without a user step lets FIRE grow its step, with the automatic step
//     as the ceiling.
#pragma once

#include "rkpm/sim/state_record.hpp"

namespace rkpm::sim {

struct IntegratorSettings;

class StepSizePolicy {
 public:
  explicit StepSizePolicy(const IntegratorSettings& settings);

  // The first step, from the stable step at the start.
  void start(double stable_dt);
  // A new estimate of the stable step (every stable_step_interval steps).
  void follow(double stable_dt);
  // FIRE's own choice of the next step (it never exceeds ceiling()).
  void take_fire_step(double dt) { dt_ = dt; }

  double dt() const { return dt_; }
  double stable_dt() const { return stable_dt_; }
  // dt_safety times the stable step: the automatic step, and FIRE's ceiling.
  double ceiling() const;
  bool clamped() const { return clamped_; }

  // Checkpoint fields "dt", "stable_dt", "dt_clamped".
  void save(StateRecord& record) const;
  void load(const StateRecord& record);

 private:
  // A user step above the stable step becomes the automatic step, once and for good.
  void clamp_user_step();

  const IntegratorSettings& settings_;
  double dt_ = 0.0, stable_dt_ = 0.0;
  bool clamped_ = false;
};

}  // namespace rkpm::sim
