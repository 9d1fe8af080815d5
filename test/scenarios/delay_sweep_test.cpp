// The delay sweep's model (scenarios/delay_sweep.h) shows what the issue asks of it: without the
// passivity controller a delayed link makes energy and the contact buzzes on, with it the device
// port stays passive up to a 30 ms round trip (jitter and loss included) and no oscillation is
// sustained; free motion is untouched; a trial repeats bit for bit.
#include "god_finger/scenarios/delay_sweep.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace god_finger
{
namespace
{
DelayTrialResult run(DelayTask task, DelayOperator op, double round_trip, double jitter, double loss, bool controller)
{
  DelayTrial trial;
  trial.task = task;
  trial.op = op;
  trial.round_trip = round_trip;
  trial.jitter_fraction = jitter;
  trial.loss = loss;
  trial.controller = controller;
  const DelayTrialResult result = runDelayTrial(trial);
  std::printf("[ measured ] %s\n", delayTrialJson(trial, result).c_str());
  return result;
}

TEST(DelaySweep, WithoutTheControllerADelayedContactMakesEnergyAndBuzzes)
{
  for (const DelayTask task : {DelayTask::kPress, DelayTask::kTap, DelayTask::kGrasp})
  {
    const DelayTrialResult off = run(task, DelayOperator::kWorstCase, 0.03, 0.2, 0.02, false);
    EXPECT_LT(off.lowest_energy_J, -1.0) << delayTaskName(task);
    EXPECT_TRUE(off.sustained) << delayTaskName(task);
    EXPECT_EQ(off.damped_ticks, 0) << delayTaskName(task);
  }
}

TEST(DelaySweep, WithItTheDevicePortStaysPassiveAtEveryRoundTripAndNoOscillationIsSustained)
{
  // Before the controller's cut (haptics/passivity_controller.h), the damper alone let a first
  // contact make up to 0.028 J from 60 ms on (a tap through 100 ms); now none goes below -1e-4 J.
  for (const DelayTask task : {DelayTask::kPress, DelayTask::kTap, DelayTask::kGrasp})
  {
    for (const double round_trip : {0.01, 0.03, 0.06, 0.1})
    {
      for (const double jitter : {0.0, 0.5})
      {
        for (const double loss : {0.0, 0.02})
        {
          const DelayTrialResult on = run(task, DelayOperator::kWorstCase, round_trip, jitter, loss, true);
          EXPECT_GE(on.lowest_energy_J, -1e-4) << delayTaskName(task) << " " << round_trip;
          EXPECT_FALSE(on.sustained) << delayTaskName(task) << " " << round_trip;
          EXPECT_LT(on.late_hf_rms_N, 0.5 * on.early_hf_rms_N + 1e-12) << delayTaskName(task) << " " << round_trip;
          EXPECT_LE(on.peak_force_N, on.max_force_N);
          // The human-like operator's tremor may come back through a passive loop (its 9 Hz at
          // 10 ms, on and off alike), but never with energy made.
          const DelayTrialResult human = run(task, DelayOperator::kHumanLike, round_trip, jitter, loss, true);
          EXPECT_GE(human.lowest_energy_J, -1e-4) << delayTaskName(task) << " " << round_trip;
          EXPECT_LE(human.peak_force_N, human.max_force_N);
          if (round_trip > 0.01)
          {
            EXPECT_FALSE(human.sustained) << delayTaskName(task) << " " << round_trip;
          }
        }
      }
    }
  }
}

TEST(DelaySweep, FreeMotionFeelsNothingAndNoLinkIsLeftAlone)
{
  for (const bool controller : {false, true})
  {
    const DelayTrialResult free = run(DelayTask::kFree, DelayOperator::kHumanLike, 0.1, 0.5, 0.02, controller);
    EXPECT_EQ(free.peak_force_N, 0.0);
    EXPECT_EQ(free.damped_ticks, 0);
  }
  // No link: the coupling's own stiffness is felt (400 N/m), the controller never acts.
  const DelayTrialResult press = run(DelayTask::kPress, DelayOperator::kWorstCase, 0.0, 0.0, 0.0, true);
  EXPECT_NEAR(press.felt_stiffness_N_per_m, 400.0, 1.0);
  EXPECT_EQ(press.damped_ticks, 0);
  EXPECT_EQ(press.lowest_energy_J, 0.0);
}

TEST(DelaySweep, ATrialRepeatsBitForBit)
{
  DelayTrial trial;
  trial.task = DelayTask::kGrasp;
  trial.op = DelayOperator::kHumanLike;
  trial.round_trip = 0.06;
  trial.jitter_fraction = 0.5;
  trial.loss = 0.02;
  EXPECT_EQ(delayTrialJson(trial, runDelayTrial(trial)), delayTrialJson(trial, runDelayTrial(trial)));
  // 4 tasks x 2 operators x (the no-link baseline + 4 round trips x 3 jitters x 2 losses) x off, on.
  EXPECT_EQ(delaySweep().size(), 4u * 2u * (1u + 4u * 3u * 2u) * 2u);
}
}  // namespace
}  // namespace god_finger
