// The step each mode takes given the stable step (rkpm/sim/step_size_policy.hpp): a
// user's step kept while stable and clamped for good once not, the automatic step of a
// dynamic run, FIRE's own step under its ceiling, and the checkpoint fields.
#include "rkpm/sim/integrator.hpp"
#include "rkpm/sim/step_size_policy.hpp"

#include <gtest/gtest.h>

namespace rkpm::sim {
namespace {

IntegratorSettings settings(Mode mode, double user_dt) {
  IntegratorSettings s;
  s.mode = mode;
  s.dt = user_dt;
  s.dt_safety = 0.5;
  return s;
}

TEST(StepSizePolicy, DynamicRunTakesTheAutomaticStepAndFollowsTheEstimate) {
  const IntegratorSettings s = settings(Mode::Dynamic, 0.0);
  StepSizePolicy policy(s);
  policy.start(2e-9);
  EXPECT_DOUBLE_EQ(policy.dt(), 1e-9);
  policy.follow(4e-9);  // a softer state: the step grows with it
  EXPECT_DOUBLE_EQ(policy.dt(), 2e-9);
  policy.follow(1e-9);
  EXPECT_DOUBLE_EQ(policy.dt(), 0.5e-9);
  EXPECT_FALSE(policy.clamped());
}

TEST(StepSizePolicy, UserStepIsKeptWhileStableThenClampedForGood) {
  const IntegratorSettings s = settings(Mode::Dynamic, 1.5e-9);
  StepSizePolicy policy(s);
  policy.start(2e-9);
  EXPECT_DOUBLE_EQ(policy.dt(), 1.5e-9);  // above the automatic step, below the stable one: kept
  policy.follow(1e-9);                    // the state stiffened past it
  EXPECT_TRUE(policy.clamped());
  EXPECT_DOUBLE_EQ(policy.dt(), 0.5e-9);
  policy.follow(8e-9);  // once clamped, the automatic step, not the user's again
  EXPECT_DOUBLE_EQ(policy.dt(), 4e-9);
}

TEST(StepSizePolicy, UserStepAboveTheStableStepAtTheStartIsClamped) {
  IntegratorSettings s = settings(Mode::Dynamic, 5e-9);
  StepSizePolicy policy(s);
  policy.start(2e-9);
  EXPECT_TRUE(policy.clamped());
  EXPECT_DOUBLE_EQ(policy.dt(), 1e-9);
  s.allow_unstable_dt = true;  // testing runs keep it
  StepSizePolicy unstable(s);
  unstable.start(2e-9);
  EXPECT_FALSE(unstable.clamped());
  EXPECT_DOUBLE_EQ(unstable.dt(), 5e-9);
}

TEST(StepSizePolicy, RelaxationKeepsFiresStepUnderTheCeiling) {
  const IntegratorSettings s = settings(Mode::Relax, 0.0);
  StepSizePolicy policy(s);
  policy.start(2e-9);
  EXPECT_DOUBLE_EQ(policy.ceiling(), 1e-9);
  policy.take_fire_step(0.3e-9);  // FIRE shrank it after an uphill step
  policy.follow(2e-9);
  EXPECT_DOUBLE_EQ(policy.dt(), 0.3e-9);  // not raised to the ceiling: FIRE grows it itself
  policy.follow(0.4e-9);
  EXPECT_DOUBLE_EQ(policy.dt(), 0.2e-9);  // but never above it
}

TEST(StepSizePolicy, CheckpointFieldsRestoreTheState) {
  const IntegratorSettings s = settings(Mode::Dynamic, 1.5e-9);
  StepSizePolicy policy(s);
  policy.start(2e-9);
  policy.follow(1e-9);
  StateRecord record;
  policy.save(record);
  StepSizePolicy restored(s);
  restored.load(record);
  EXPECT_EQ(restored.dt(), policy.dt());
  EXPECT_EQ(restored.stable_dt(), policy.stable_dt());
  EXPECT_TRUE(restored.clamped());
}

}  // namespace
}  // namespace rkpm::sim
