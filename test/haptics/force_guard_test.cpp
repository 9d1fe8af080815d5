// ForceGuard: saturation, NaN/Inf rejection, the watchdog's ramp to zero within ramp_time, the
// soft start, the rate limit, stop and resume, the continuous (thermal-like) budget.
#include "god_finger/haptics/force_guard.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace god_finger
{
namespace
{
// The device limit of the tests that do not test saturation (N).
constexpr double kMaxForce = 8.0;

// The rules that are not under test off: no soft start, a rate limit that never binds.
ForceGuardParams immediate()
{
  ForceGuardParams params;
  params.soft_start = 0.0;
  params.max_force_rate = 1e6;
  return params;
}

TEST(ForceGuard, SaturatesKeepingTheDirection)
{
  ForceGuard guard(3.3, immediate());
  guard.output(0.0);
  EXPECT_TRUE(guard.command(0.0, Eigen::Vector3d(3.0, 4.0, 0.0)));
  EXPECT_NEAR(guard.commanded().norm(), 3.3, 1e-12);
  const Eigen::Vector3d out = guard.output(0.001);
  EXPECT_NEAR(out.norm(), 3.3, 1e-12);
  EXPECT_NEAR(out.x() / out.y(), 0.75, 1e-12);
  EXPECT_EQ(guard.saturated(), 1);
  EXPECT_TRUE(guard.command(0.001, Eigen::Vector3d(1.0, 0.0, 0.0)));
  EXPECT_EQ(guard.output(0.002), Eigen::Vector3d(1.0, 0.0, 0.0));
}

TEST(ForceGuard, RejectsNonFiniteCommandsAndKeepsTheLastGoodOne)
{
  ForceGuard guard(kMaxForce, immediate());
  guard.output(0.0);
  guard.command(0.0, Eigen::Vector3d(1, 2, 3));
  EXPECT_FALSE(guard.command(0.001, Eigen::Vector3d(NAN, 0, 0)));
  EXPECT_FALSE(guard.command(0.002, Eigen::Vector3d(0, INFINITY, 0)));
  EXPECT_FALSE(guard.command(0.003, Eigen::Vector3d(0, 0, -INFINITY)));
  EXPECT_EQ(guard.rejected(), 3);
  EXPECT_EQ(guard.output(0.003), Eigen::Vector3d(1, 2, 3));
}

TEST(ForceGuard, NothingBeforeTheFirstCommand)
{
  ForceGuard guard(kMaxForce, ForceGuardParams{});
  EXPECT_EQ(guard.output(5.0), Eigen::Vector3d::Zero());
}

TEST(ForceGuard, WatchdogRampsToZeroWithinRampTimeAfterTheTimeout)
{
  ForceGuardParams params = immediate();  // 20 ms timeout, 10 ms ramp
  ForceGuard guard(kMaxForce, params);
  guard.output(0.999);
  guard.command(1.0, Eigen::Vector3d(0, 0, 4.0));
  EXPECT_EQ(guard.output(1.0 + 0.0199), Eigen::Vector3d(0, 0, 4.0));  // up to the timeout: full
  EXPECT_FALSE(guard.timedOut(1.0199));
  EXPECT_NEAR(guard.output(1.0 + 0.025).z(), 2.0, 1e-9);  // half-way down the ramp
  EXPECT_TRUE(guard.timedOut(1.025));
  EXPECT_EQ(guard.output(1.0 + 0.030 + 1e-9), Eigen::Vector3d::Zero());  // zero 10 ms after the timeout
  EXPECT_EQ(guard.output(100.0), Eigen::Vector3d::Zero());
  // A new command applies at the next output (no soft start here; see ResumesWithTheSoftStart).
  guard.command(100.0, Eigen::Vector3d(1, 0, 0));
  EXPECT_EQ(guard.output(100.001), Eigen::Vector3d(1, 0, 0));
  // The output never exceeds the last command along the ramp.
  for (double t = 100.0; t < 100.05; t += 1e-4)
  {
    EXPECT_LE(guard.output(t).norm(), 1.0 + 1e-12);
  }
}

TEST(ForceGuard, BadParametersAreNamed)
{
  ForceGuardParams params;
  try
  {
    ForceGuard guard(-1.0, params);
    ADD_FAILURE() << "a negative max_force was taken";
  }
  catch (const InputError& error)
  {
    EXPECT_STREQ(error.what(), "parameter 'max_force' = -1 is out of range (0, 10000] (N)");
  }
  params.command_timeout = 0.0;
  EXPECT_THROW(ForceGuard(kMaxForce, params), InputError);
  params.command_timeout = 0.0;
  EXPECT_EQ(validate(params), "parameter 'command_timeout' = 0 is out of range (0, 10] (s)");
  params = ForceGuardParams();
  params.ramp_time = NAN;
  EXPECT_EQ(validate(params), "parameter 'ramp_time' = nan is out of range (0, 1] (s)");
  params = ForceGuardParams();
  params.soft_start = -0.1;
  EXPECT_EQ(validate(params), "parameter 'soft_start' = -0.1 is out of range [0, 10] (s)");
  params = ForceGuardParams();
  params.max_force_rate = 0.0;
  EXPECT_EQ(validate(params), "parameter 'max_force_rate' = 0 is out of range (0, 1000000] (N/s)");
}

constexpr double kPeriod = 1e-3;

TEST(ForceGuard, SoftStartRampsInFromZero)
{
  ForceGuardParams params;  // soft_start 0.5 s, 1e4 N/s
  ForceGuard guard(kMaxForce, params);
  const Eigen::Vector3d command(0, 0, 5.0);
  double previous = 0.0;
  for (int k = 0; k <= 600; ++k)
  {
    const double t = k * kPeriod;
    const double out = guard.output(t).z();
    if (k == 0)
    {
      EXPECT_EQ(out, 0.0);  // nothing before the first command
    }
    guard.command(t, command);
    if (k == 1)
    {
      EXPECT_NEAR(out, 5.0 * kPeriod / 0.5, 1e-9);  // the ramp's first step, not the command
    }
    EXPECT_GE(out, previous - 1e-12) << "monotonic ramp, tick " << k;
    EXPECT_LE(out, 5.0 * t / 0.5 + 1e-9) << "tick " << k;
    if (k == 500)
    {
      EXPECT_NEAR(out, 5.0, 1e-9);  // reached at soft_start
    }
    previous = out;
  }
  EXPECT_EQ(guard.output(0.6001).z(), 5.0);  // the command since soft_start (0.5 s)
}

TEST(ForceGuard, RateLimitBoundsEveryStep)
{
  ForceGuardParams params;
  params.soft_start = 0.0;
  params.max_force_rate = 1000.0;  // 1 N per ms
  ForceGuard guard(kMaxForce, params);
  Eigen::Vector3d last = guard.output(0.0);
  double largest = 0.0;
  bool reached = false;
  for (int k = 0; k < 100; ++k)
  {
    const double t = k * kPeriod;
    // Steps of 8 N back and forth every 20 ms, and a sideways jump.
    const Eigen::Vector3d command = (k / 20) % 2 == 0 ? Eigen::Vector3d(8, 0, 0) : Eigen::Vector3d(0, -8, 0);
    guard.command(t, command);
    const Eigen::Vector3d out = guard.output(t + kPeriod);
    largest = std::max(largest, (out - last).norm());
    reached = reached || (out - command).norm() < 1e-9;
    last = out;
  }
  EXPECT_LE(largest, 1.0 + 1e-9);
  EXPECT_GT(largest, 0.999);  // it did bind
  EXPECT_TRUE(reached);       // and the command is reached (8 N in 8 ms, within the 20 ms)
}

TEST(ForceGuard, StopZeroesAtOnceAndResumeRampsIn)
{
  ForceGuardParams params;  // soft_start 0.5 s
  ForceGuard guard(kMaxForce, params);
  const Eigen::Vector3d command(2, 0, 0);
  double t = 0.0;
  for (; t < 1.0; t += kPeriod)
  {
    guard.command(t, command);
    guard.output(t);
  }
  EXPECT_EQ(guard.output(t), command);
  guard.stop();
  EXPECT_TRUE(guard.stopped());
  EXPECT_EQ(guard.output(t), Eigen::Vector3d::Zero());  // at once, even at the same time
  for (; t < 2.0; t += kPeriod)
  {
    guard.command(t, command);
    ASSERT_EQ(guard.output(t), Eigen::Vector3d::Zero()) << t;
  }
  const double resumed = t;
  guard.resume(resumed);
  EXPECT_FALSE(guard.stopped());
  for (; t < resumed + 0.6; t += kPeriod)
  {
    guard.command(t, command);
    const double out = guard.output(t).x();
    ASSERT_LE(out, 2.0 * (t - resumed) / 0.5 + 1e-9) << t;  // the soft start again
  }
  EXPECT_EQ(guard.output(t), command);
}

// scale(): the factor the force's target gets from the watchdog, the soft start and stop (an
// oriented finger's torque is scaled by it): 0 before the first command, the soft start's
// (t - t0) / soft_start, the watchdog's ramp, 0 while stopped and the soft start again on resume.
TEST(ForceGuard, ScaleIsTheSoftStartTimesTheWatchdogAndZeroWhenStopped)
{
  ForceGuardParams params;  // soft_start 0.5 s, command_timeout 20 ms, ramp_time 10 ms
  ForceGuard guard(kMaxForce, params);
  const Eigen::Vector3d command(1, 0, 0);
  EXPECT_EQ(guard.scale(0.0), 0.0);  // no command yet
  guard.command(1.0, command);
  EXPECT_EQ(guard.scale(1.0), 0.0);
  EXPECT_NEAR(guard.scale(1.01), 0.02, 1e-12);  // within the timeout: the soft start alone
  double last = 1.0;                            // the last command's time
  for (double t = 1.0; t <= 1.6; t += kPeriod)
  {
    guard.command(t, command);
    last = t;
    ASSERT_NEAR(guard.scale(t), std::min(1.0, (t - 1.0) / 0.5), 1e-12) << t;
    guard.output(t);
  }
  // The force's own target is the same factor times the command (the rate limit does not bind
  // at 1e4 N/s): no second ramp.
  EXPECT_NEAR(guard.output(last).x(), guard.scale(last) * command.x(), 1e-12);
  EXPECT_EQ(guard.scale(last), 1.0);
  // The watchdog (20 ms without a command), 5 ms into its 10 ms ramp: half.
  EXPECT_NEAR(guard.scale(last + 0.02 + 0.005), 0.5, 1e-9);
  EXPECT_EQ(guard.scale(last + 0.02 + 0.011), 0.0);
  guard.command(2.0, command);  // after the watchdog tripped: the soft start again
  EXPECT_NEAR(guard.scale(2.01), 0.02, 1e-12);
  guard.stop();
  EXPECT_EQ(guard.scale(2.01), 0.0);
  guard.command(2.015, command);
  EXPECT_EQ(guard.scale(2.015), 0.0);  // commands are taken while stopped, nothing goes out
  guard.resume(2.015);
  for (double t = 2.015; t < 2.265; t += kPeriod)
  {
    guard.command(t, command);
  }
  EXPECT_NEAR(guard.scale(2.265), 0.5, 1e-9);  // 0.25 s into the soft start
}

TEST(ForceGuard, ResumesWithTheSoftStartAfterTheWatchdog)
{
  ForceGuardParams params;
  ForceGuard guard(kMaxForce, params);
  for (double t = 0.0; t < 1.0; t += kPeriod)
  {
    guard.command(t, Eigen::Vector3d(0, 1, 0));
    guard.output(t);
  }
  EXPECT_EQ(guard.output(1.0).y(), 1.0);
  EXPECT_EQ(guard.output(2.0).y(), 0.0);  // watchdog
  guard.command(2.0, Eigen::Vector3d(0, 1, 0));
  EXPECT_NEAR(guard.output(2.001).y(), kPeriod / 0.5, 1e-9);  // not the step
}

// The Omni: 3.3 N peak, 0.88 N continuous, tau 10 s.
constexpr double kOmniMaxForce = 3.3;
ForceGuardParams omni()
{
  ForceGuardParams params;
  params.soft_start = 0.0;
  params.max_force_rate = 1000.0;
  params.continuous_force = 0.88;
  params.thermal_time_constant = 10.0;
  return params;
}

TEST(ForceGuard, HeldPeakFallsToTheContinuousLimit)
{
  ForceGuard guard(kOmniMaxForce, omni());
  guard.output(0.0);
  // From cold, a held F may stay over Fc for tau ln(F^2 / (F^2 - Fc^2)): 0.90 s for 3 N.
  const double budget = 10.0 * std::log(9.0 / (9.0 - 0.88 * 0.88));
  double t = 0.0;
  double over_until = 0.0;
  for (int k = 1; k <= 3000; ++k)
  {
    t = k * kPeriod;
    guard.command(t, Eigen::Vector3d(3.0, 0, 0));
    const double out = guard.output(t).norm();
    ASSERT_LE(out, 3.0 + 1e-12);
    if (out > 0.88 + 1e-6)
    {
      over_until = t;
    }
  }
  EXPECT_GT(over_until, budget - 0.05);  // the peak allowance was used
  EXPECT_LE(over_until, budget + 0.05);  // and no longer
  EXPECT_NEAR(guard.output(t + kPeriod).norm(), 0.88, 1e-3);
  EXPECT_LE(guard.thermalLoad(), 0.88 * 0.88 + 0.01);
  EXPECT_GT(guard.budgetLimited(), 0);
}

TEST(ForceGuard, ShortPeakPassesTheContinuousLimit)
{
  ForceGuard guard(kOmniMaxForce, omni());
  guard.output(0.0);
  for (int k = 1; k <= 200; ++k)  // 0.2 s of 3 N
  {
    const double t = k * kPeriod;
    guard.command(t, Eigen::Vector3d(0, 0, -3.0));
    const Eigen::Vector3d out = guard.output(t);
    if (k > 3)  // after the rate limit's 3 ms
    {
      ASSERT_EQ(out, Eigen::Vector3d(0, 0, -3.0)) << k;
    }
  }
  EXPECT_EQ(guard.budgetLimited(), 0);
}
}  // namespace
}  // namespace god_finger
