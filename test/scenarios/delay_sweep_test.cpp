// The delay sweep's model (scenarios/delay_sweep.h) shows what the issue asks of it: without the
// passivity controller a delayed link makes energy and the contact buzzes on, with it the device
// port stays passive through 10-100 ms round trips (jitter and loss included); free motion is
// untouched when forces are forwarded; a trial repeats bit for bit. And what the local coupling
// (the haptic node's default) gives: passive on a wall, a drag in free motion.
#include "god_finger/scenarios/delay_sweep.h"
#include "god_finger/haptics/passivity_controller.h"
#include "god_finger/haptics/virtual_coupling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace god_finger
{
namespace
{
DelayTrialResult run(DelayTask task, DelayOperator op, double round_trip, double jitter, double loss, bool controller,
                     bool local_coupling = false)
{
  DelayTrial trial;
  trial.local_coupling = local_coupling;
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
          // The human-like operator: passive too, and once the hand stops trembling (the last
          // 1.5 s) nothing rings on.
          const DelayTrialResult human = run(task, DelayOperator::kHumanLike, round_trip, jitter, loss, true);
          EXPECT_GE(human.lowest_energy_J, -1e-4) << delayTaskName(task) << " " << round_trip;
          EXPECT_LE(human.peak_force_N, human.max_force_N);
          EXPECT_FALSE(human.sustained) << delayTaskName(task) << " " << round_trip;
          EXPECT_LT(human.late_hf_rms_N, 0.5 * human.early_hf_rms_N) << delayTaskName(task) << " " << round_trip;
        }
      }
    }
  }
}

// The tremor is a forcing: through a 10 ms link the human-like hand's 9 Hz comes back stronger
// than with no link (the delayed loop's resonance, near 11 Hz, less damped), on and off alike and
// without energy made; when the hand stops trembling it dies. Counted in the run's last second
// with the tremor still on, as the sweep did before, the press read as sustained: the forced
// answer is transparency (tremor_hf_rms_N against the no-link run's), not an oscillation of the
// loop's own.
TEST(DelaySweep, TheTremorIsAForcingTheLoopAnswersAndForgets)
{
  for (const bool controller : {false, true})
  {
    const DelayTrialResult press = run(DelayTask::kPress, DelayOperator::kHumanLike, 0.01, 0.2, 0.0, controller);
    const double gain = press.tremor_hf_rms_N / press.baseline_tremor_hf_rms_N;
    std::printf("tremor felt through 10 ms: %.4f N rms above 5 Hz, %.2f of the no-link run's; after it: %.5f N\n",
                press.tremor_hf_rms_N, gain, press.late_hf_rms_N);
    EXPECT_GT(gain, 1.3);
    EXPECT_GT(press.tremor_hf_rms_N, press.baseline_tremor_hf_rms_N + kSustainedHfRms);
    EXPECT_GE(press.lowest_energy_J, 0.0);
    EXPECT_EQ(press.damped_ticks, 0);
    EXPECT_LT(press.late_hf_rms_N, 0.05 * press.tremor_hf_rms_N);
    EXPECT_FALSE(press.sustained);
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
  // 4 tasks x 2 operators x (the no-link baseline + 4 round trips x 3 jitters x 2 losses) x off,
  // on at the device port, on at both ports.
  EXPECT_EQ(delaySweep().size(), 4u * 2u * (1u + 4u * 3u * 2u) * 3u);
  trial.form = PassivityForm::kTwoPort;
  EXPECT_EQ(delayTrialJson(trial, runDelayTrial(trial)), delayTrialJson(trial, runDelayTrial(trial)));
}

// The channel as a two-port (haptics/two_port_passivity.h): each side's margin, the energy the
// other put in as its packets said less what this side let out. The two-port form adds the
// physics side's controller to the device's one-port one: the physics' margin is held to the
// contact's credit (passivity_contact_credit) at every contact setting, through jitter and loss,
// the hand stays passive and nothing rings; with the device's controller alone the physics'
// margin falls far below (the test can fail). The device side's margin is counted, not held: its
// controller, tried, rang (docs/decisions.md); the hand's own energy is what the one-port holds.
TEST(DelaySweep, TheTwoPortFormHoldsThePhysicsMarginToTheCreditAndNothingRings)
{
  const double credit = PassivityParams{}.passivity_contact_credit;
  double lowest_device_margin = 0.0;
  for (const DelayTask task : {DelayTask::kPress, DelayTask::kTap, DelayTask::kGrasp})
  {
    for (const DelayOperator op : {DelayOperator::kWorstCase, DelayOperator::kHumanLike})
    {
      for (const double round_trip : {0.01, 0.03, 0.06, 0.1})
      {
        for (const double jitter : {0.0, 0.5})
        {
          DelayTrial trial;
          trial.task = task;
          trial.op = op;
          trial.round_trip = round_trip;
          trial.jitter_fraction = jitter;
          trial.loss = 0.02;
          trial.form = PassivityForm::kTwoPort;
          const DelayTrialResult two = runDelayTrial(trial);
          std::printf("[ measured ] %s\n", delayTrialJson(trial, two).c_str());
          const std::string where = std::string(delayTaskName(task)) + " " + delayOperatorName(op) + " " +
                                    std::to_string(round_trip) + " " + std::to_string(jitter);
          EXPECT_GE(two.physics_margin_J, -credit - 1e-12) << where;
          EXPECT_GE(two.lowest_energy_J, -1e-4) << where;
          EXPECT_FALSE(two.sustained) << where;
          EXPECT_GT(two.peak_force_N, 1.0) << where;  // the contact started
          EXPECT_LE(two.peak_force_N, two.max_force_N) << where;
          EXPECT_GT(two.damped_ticks, 0) << where;
          lowest_device_margin = std::min(lowest_device_margin, two.device_margin_J);
          trial.form = PassivityForm::kDevicePort;
          const DelayTrialResult one = runDelayTrial(trial);
          EXPECT_LT(one.physics_margin_J, -4.0 * credit) << where;  // measured: -4.6e-4 J at least
          EXPECT_EQ(one.max_drift_m, 0.0);
          trial.controller = false;
          const DelayTrialResult off = runDelayTrial(trial);
          EXPECT_LT(std::min(off.device_margin_J, off.physics_margin_J),
                    op == DelayOperator::kWorstCase ? -0.1 : -4.0 * credit)
              << where;
        }
      }
    }
  }
  std::printf("[ measured ] the two-port form's lowest device margin (counted, not held): %.3g J\n",
              lowest_device_margin);
}

// The two-port form's first contact (two_port_passivity_test: on the credit): in free motion the
// device renders no force and puts no energy in; the physics lends the credit, the wall's first
// force reaches the hand, and its push pays for the rest. With no link it renders the wall as the
// device port's form does (until the credit, no contact ever started: the hand sank through the
// wall feeling nothing).
TEST(DelaySweep, TheTwoPortFormStartsAContactOnTheCredit)
{
  for (const DelayTask task : {DelayTask::kPress, DelayTask::kTap, DelayTask::kGrasp})
  {
    DelayTrial trial;
    trial.task = task;
    trial.form = PassivityForm::kTwoPort;
    const DelayTrialResult two = runDelayTrial(trial);
    trial.form = PassivityForm::kDevicePort;
    const DelayTrialResult one = runDelayTrial(trial);
    EXPECT_GT(two.peak_force_N, 2.0) << delayTaskName(task);
    EXPECT_NEAR(two.peak_force_N, one.peak_force_N, 0.05 * one.peak_force_N) << delayTaskName(task);
    EXPECT_GE(two.physics_margin_J, -PassivityParams{}.passivity_contact_credit - 1e-12) << delayTaskName(task);
    if (task == DelayTask::kPress)
    {
      EXPECT_NEAR(two.felt_stiffness_N_per_m, 400.0, 1.0);
      EXPECT_EQ(two.max_drift_m, 0.0);
    }
  }
}

// The haptic node's default across processes, the local coupling (the spring rendered on the
// device's side against the last god-object received), measured here because the sweep's rows
// forward forces. Pressing a stiff wall through a 30 ms round trip it stays passive with the
// controller off (what link.test shows through ROS). In free motion its god-object lags the hand
// by the round trip, so the hand feels a drag of about k T: this pins what the default does
// today (docs/devices.md; issue 29's note), until the god-object is predicted or the spring held
// off while the physics reports it free. (The human-like hand also rings against that delayed
// spring from 30 ms on: the run's last second holds 0.40 N rms above 5 Hz at 30 ms, 0.44 N at
// 100 ms, printed as "sustained" in the [ measured ] lines; not asserted here.)
// The haptic node's local coupling (ros/haptic_node.h): the spring rendered at the device
// against the last god-object that came, predicted as the servo loop's hold does
// (runtime/multirate_render.h: a god-object on the step's contact planes). Free motion is free
// through any round trip (a fixed god-object dragged the hand by about k T v: 1.30, 3.02 and 7.74 N
// at 10, 30 and 100 ms until stop 44); a wall comes half a round trip late, so without the
// controller a press makes energy (the hand entered unresisted, the spring pushes it out), and
// with the controller, the default, the port stays passive and nothing rings.
TEST(DelaySweep, TheLocalCouplingIsFreeInFreeMotionAndPassiveOnAWallWithTheController)
{
  for (const double round_trip : {0.03, 0.1})
  {
    const DelayTrialResult off =
        run(DelayTask::kPress, DelayOperator::kWorstCase, round_trip, 0.0, 0.0, false, /*local_coupling=*/true);
    const DelayTrialResult on =
        run(DelayTask::kPress, DelayOperator::kWorstCase, round_trip, 0.0, 0.0, true, /*local_coupling=*/true);
    // Measured: -6.6e-5 J through 30 ms, -4.0e-4 J through 100 ms without; >= 0 with.
    EXPECT_LT(off.lowest_energy_J, round_trip >= 0.1 ? -1e-4 : 0.0) << round_trip;
    EXPECT_GE(on.lowest_energy_J, -1e-4) << round_trip;
    EXPECT_GT(on.damped_ticks, 0) << round_trip;
    EXPECT_FALSE(on.sustained) << round_trip;
    EXPECT_GT(on.felt_stiffness_N_per_m, 150.0) << round_trip;
  }
  for (const double round_trip : {0.01, 0.03, 0.1})
  {
    const DelayTrialResult local =
        run(DelayTask::kFree, DelayOperator::kHumanLike, round_trip, 0.0, 0.0, true, /*local_coupling=*/true);
    EXPECT_EQ(local.peak_force_N, 0.0) << round_trip;
  }
}
}  // namespace
}  // namespace god_finger
