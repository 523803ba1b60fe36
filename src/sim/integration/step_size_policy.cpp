#include "rkpm/sim/step_size_policy.hpp"

#include "rkpm/sim/integrator.hpp"

#include <algorithm>

namespace rkpm::sim {

StepSizePolicy::StepSizePolicy(const IntegratorSettings& settings) : settings_(settings) {}

double StepSizePolicy::ceiling() const { return settings_.dt_safety * stable_dt_; }

void StepSizePolicy::start(double stable_dt) {
  stable_dt_ = stable_dt;
  clamped_ = false;
  dt_ = settings_.dt > 0.0 ? settings_.dt : ceiling();
  clamp_user_step();
}

void StepSizePolicy::follow(double stable_dt) {
  stable_dt_ = stable_dt;
  if (settings_.dt > 0.0 && !clamped_)
    clamp_user_step();
  else if (settings_.mode == Mode::Dynamic || clamped_)
    dt_ = ceiling();
  else
    dt_ = std::min(dt_, ceiling());
}

void StepSizePolicy::clamp_user_step() {
  if (settings_.dt > 0.0 && !clamped_ && dt_ > stable_dt_ && !settings_.allow_unstable_dt) {
    dt_ = ceiling();
    clamped_ = true;
  }
}

void StepSizePolicy::save(StateRecord& record) const {
  record.put_real("dt", dt_);
  record.put_real("stable_dt", stable_dt_);
  record.put_integer("dt_clamped", clamped_ ? 1 : 0);
}

void StepSizePolicy::load(const StateRecord& record) {
  dt_ = record.real("dt");
  stable_dt_ = record.real("stable_dt");
  clamped_ = record.integer("dt_clamped") != 0;
}

}  // namespace rkpm::sim
