// ForceGuard: saturation, NaN/Inf rejection, the watchdog's ramp to zero within ramp_time.
#include "god_finger/core/force_guard.h"
#include "god_finger/core/input_error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace god_finger
{
namespace
{
TEST(ForceGuard, SaturatesKeepingTheDirection)
{
  ForceGuardParams params;
  params.max_force = 3.3;
  ForceGuard guard(params);
  EXPECT_TRUE(guard.command(0.0, Eigen::Vector3d(3.0, 4.0, 0.0)));
  const Eigen::Vector3d out = guard.output(0.0);
  EXPECT_NEAR(out.norm(), 3.3, 1e-12);
  EXPECT_NEAR(out.x() / out.y(), 0.75, 1e-12);
  EXPECT_EQ(guard.saturated(), 1);
  EXPECT_TRUE(guard.command(0.001, Eigen::Vector3d(1.0, 0.0, 0.0)));
  EXPECT_EQ(guard.output(0.001), Eigen::Vector3d(1.0, 0.0, 0.0));
}

TEST(ForceGuard, RejectsNonFiniteCommandsAndKeepsTheLastGoodOne)
{
  ForceGuard guard(ForceGuardParams{});
  guard.command(0.0, Eigen::Vector3d(1, 2, 3));
  EXPECT_FALSE(guard.command(0.001, Eigen::Vector3d(NAN, 0, 0)));
  EXPECT_FALSE(guard.command(0.002, Eigen::Vector3d(0, INFINITY, 0)));
  EXPECT_FALSE(guard.command(0.003, Eigen::Vector3d(0, 0, -INFINITY)));
  EXPECT_EQ(guard.rejected(), 3);
  EXPECT_EQ(guard.output(0.003), Eigen::Vector3d(1, 2, 3));
}

TEST(ForceGuard, NothingBeforeTheFirstCommand)
{
  ForceGuard guard(ForceGuardParams{});
  EXPECT_EQ(guard.output(5.0), Eigen::Vector3d::Zero());
}

TEST(ForceGuard, WatchdogRampsToZeroWithinRampTimeAfterTheTimeout)
{
  ForceGuardParams params;  // 20 ms timeout, 10 ms ramp
  ForceGuard guard(params);
  guard.command(1.0, Eigen::Vector3d(0, 0, 4.0));
  EXPECT_EQ(guard.output(1.0 + 0.0199), Eigen::Vector3d(0, 0, 4.0));  // up to the timeout: full
  EXPECT_FALSE(guard.timedOut(1.0199));
  EXPECT_NEAR(guard.output(1.0 + 0.025).z(), 2.0, 1e-9);  // half-way down the ramp
  EXPECT_TRUE(guard.timedOut(1.025));
  EXPECT_EQ(guard.output(1.0 + 0.030 + 1e-9), Eigen::Vector3d::Zero());  // zero 10 ms after the timeout
  EXPECT_EQ(guard.output(100.0), Eigen::Vector3d::Zero());
  // A new command applies at once.
  guard.command(100.0, Eigen::Vector3d(1, 0, 0));
  EXPECT_EQ(guard.output(100.0), Eigen::Vector3d(1, 0, 0));
  // The output never exceeds the last command along the ramp.
  for (double t = 100.0; t < 100.05; t += 1e-4)
  {
    EXPECT_LE(guard.output(t).norm(), 1.0 + 1e-12);
  }
}

TEST(ForceGuard, BadParametersAreNamed)
{
  ForceGuardParams params;
  params.max_force = -1.0;
  EXPECT_EQ(validate(params), "parameter 'max_force' = -1 is out of range (0, 10000] (N)");
  EXPECT_THROW(ForceGuard{params}, InputError);
  params = ForceGuardParams();
  params.command_timeout = 0.0;
  EXPECT_EQ(validate(params), "parameter 'command_timeout' = 0 is out of range (0, 10] (s)");
  params = ForceGuardParams();
  params.ramp_time = NAN;
  EXPECT_EQ(validate(params), "parameter 'ramp_time' = nan is out of range (0, 1] (s)");
}
}  // namespace
}  // namespace god_finger
