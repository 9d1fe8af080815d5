// The fake device against analytic answers: it follows its scripted hand, a constant force
// deflects it by F / grip stiffness, and bad parameters are named.
#include "god_finger/devices/fake_device.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace god_finger
{
namespace
{
// A list of rows, as a YAML list of lists reads.
ParameterValue table(const std::vector<std::vector<double>>& rows)
{
  ParameterValue value;
  value.kind = ParameterValue::Kind::kList;
  for (const std::vector<double>& row : rows)
  {
    value.items.push_back(ParameterValue::of(row));
  }
  return value;
}

TEST(FakeDevice, FollowsItsScriptedHand)
{
  FakeDevice device(FakeDeviceParams{},
                    WaypointPath({{0.0, Eigen::Vector3d(0, 0, 0)}, {1.0, Eigen::Vector3d(0.1, 0, 0)}}));
  DeviceReading reading;
  for (int i = 0; i <= 2000; ++i)
  {
    reading = device.update(i * 1e-3, Eigen::Vector3d::Zero());
  }
  EXPECT_NEAR(reading.position.x(), 0.1, 1e-5);
  EXPECT_NEAR(reading.velocity.norm(), 0.0, 1e-4);
}

// With repeat_return the script plays again and again: the hand goes back from the script's
// last waypoint to its first in repeat_return s, then follows the script as the first time.
// Without it (the default) the hand stays at the last waypoint.
TEST(FakeDevice, RepeatsItsScriptWhenAskedAndOtherwiseHoldsTheEnd)
{
  const WaypointPath script({{0.0, Eigen::Vector3d(0, 0, 0.1)}, {1.0, Eigen::Vector3d(0.1, 0, 0.1)}});
  FakeDeviceParams repeating;
  repeating.repeat_return = 0.5;
  FakeDevice once(FakeDeviceParams{}, script);
  FakeDevice again(repeating, script);
  std::vector<Eigen::Vector3d> first_play;
  double largest_step = 0.0;  // m per 1 ms update: no jump when the script wraps
  Eigen::Vector3d last = again.update(0.0, Eigen::Vector3d::Zero()).position;
  once.update(0.0, Eigen::Vector3d::Zero());
  DeviceReading held;
  for (int i = 1; i <= 4500; ++i)  // 4.5 s: three plays of 1.5 s
  {
    const DeviceReading reading = again.update(i * 1e-3, Eigen::Vector3d::Zero());
    held = once.update(i * 1e-3, Eigen::Vector3d::Zero());
    largest_step = std::max(largest_step, (reading.position - last).norm());
    last = reading.position;
    if (i == 1000)
    {
      EXPECT_NEAR(reading.position.x(), 0.1, 2e-3) << "the first play reaches the script's end";
    }
    if (i == 1500 || i == 3000 || i == 4500)
    {
      EXPECT_NEAR(reading.position.x(), 0.0, 2e-3) << "back at the script's start at " << i * 1e-3 << " s";
    }
    if (i == 2500 || i == 4000)
    {
      EXPECT_NEAR(reading.position.x(), 0.1, 2e-3) << "the script's end again at " << i * 1e-3 << " s";
    }
  }
  EXPECT_NEAR(held.position.x(), 0.1, 1e-5) << "without repeat_return the hand holds the last waypoint";
  EXPECT_LT(largest_step, 0.3e-3) << "the handle moves at most 0.2 m/s (the return's speed) plus its lag";
}

// An oriented script repeats its turn too: back to the first orientation on the way back.
TEST(FakeDevice, RepeatsItsOrientationScriptWithItsPositions)
{
  FakeDeviceParams repeating;
  repeating.repeat_return = 0.5;
  const Eigen::Quaterniond quarter(Eigen::AngleAxisd(M_PI / 2.0, Eigen::Vector3d::UnitX()));
  FakeDevice device(repeating, WaypointPath({{0.0, Eigen::Vector3d(0, 0, 0.1)}, {1.0, Eigen::Vector3d(0, 0, 0.1)}}),
                    OrientationPath({{0.0, Eigen::Quaterniond::Identity()}, {1.0, quarter}}));
  for (int i = 0; i <= 2500; ++i)
  {
    const DeviceReading reading = device.update(i * 1e-3, Eigen::Vector3d::Zero());
    ASSERT_TRUE(reading.has_orientation);
    if (i == 1000 || i == 2500)
    {
      EXPECT_NEAR(reading.orientation.angularDistance(quarter), 0.0, 1e-9) << "turned at " << i * 1e-3 << " s";
    }
    if (i == 1250)
    {
      EXPECT_NEAR(reading.orientation.angularDistance(Eigen::Quaterniond::Identity()), M_PI / 4.0, 1e-9)
          << "half way back";
    }
    if (i == 1500)
    {
      EXPECT_NEAR(reading.orientation.angularDistance(Eigen::Quaterniond::Identity()), 0.0, 1e-9) << "back at 1.5 s";
    }
  }
}

// An idle handle settling on a hand at x = 0 (here: after a 1 cm step) decays toward 0
// exponentially; the device ends the decay at exactly 0 instead of walking into the subnormal
// range (support/denormals.h), where x86 arithmetic is many times slower. This thread does not
// flush subnormals, so the device alone must keep them out.
TEST(FakeDevice, AnIdleHandleSettlesOnZeroWithoutSubnormals)
{
  FakeDevice device(FakeDeviceParams{},
                    WaypointPath({{0.0, Eigen::Vector3d(0.01, 0, 0.1)}, {0.05, Eigen::Vector3d(0, 0, 0.1)}}));
  long subnormal = 0;
  double settled_at = -1.0;
  for (int i = 0; i <= 600000 && settled_at < 0.0; ++i)  // up to 10 min at 1 kHz
  {
    const DeviceReading reading = device.update(i * 1e-3, Eigen::Vector3d::Zero());
    for (int k = 0; k < 3; ++k)
    {
      subnormal += std::fpclassify(reading.position[k]) == FP_SUBNORMAL ? 1 : 0;
      subnormal += std::fpclassify(reading.velocity[k]) == FP_SUBNORMAL ? 1 : 0;
    }
    if (i > 100 && reading.position.x() == 0.0 && reading.velocity.x() == 0.0)
    {
      settled_at = i * 1e-3;
    }
  }
  EXPECT_EQ(subnormal, 0);
  ASSERT_GT(settled_at, 0.0) << "the handle never settled on exactly 0";
  std::printf("idle handle: settled on exactly 0 after %.1f s, no subnormal\n", settled_at);
}

TEST(FakeDevice, ConstantForceDeflectsTheHandleByForceOverGripStiffness)
{
  FakeDeviceParams params;
  FakeDevice device(params, WaypointPath({{0.0, Eigen::Vector3d::Zero()}}));
  DeviceReading reading;
  for (int i = 0; i <= 3000; ++i)
  {
    reading = device.update(10.0 + i * 1e-3, Eigen::Vector3d(0, 0, 4.0));
  }
  EXPECT_NEAR(reading.position.z(), 4.0 / params.grip_stiffness, 1e-6);
  // A non-finite force is not applied.
  const DeviceReading same = device.update(13.001, Eigen::Vector3d(NAN, 0, 0));
  EXPECT_TRUE(same.position.allFinite());
}

// The orientation script (config/scripts/*.yaml orientation_script: [t, w, x, y, z]): slerped,
// reported with every reading; without one, no orientation (a 3-DOF finger). A torque given to
// updateWrench is recorded and moves nothing.
TEST(FakeDevice, ReportsItsOrientationScriptAndRecordsTheTorque)
{
  MapParameterSource source("test: ");
  source.set("orientation_script", table({{0.0, 1.0, 0.0, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0, 1.0}}));
  std::optional<OrientationPath> orientation = readOrientationScript(source);
  ASSERT_TRUE(orientation.has_value());
  FakeDevice oriented(FakeDeviceParams{}, WaypointPath({{0.0, Eigen::Vector3d::Zero()}}), orientation);
  FakeDevice plain(FakeDeviceParams{}, WaypointPath({{0.0, Eigen::Vector3d::Zero()}}));
  DeviceReading reading;
  DeviceReading plain_reading;
  for (int i = 0; i <= 500; ++i)
  {
    reading = oriented.updateWrench(i * 1e-3, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.01, 0.0));
    plain_reading = plain.update(i * 1e-3, Eigen::Vector3d::Zero());
  }
  ASSERT_TRUE(reading.has_orientation);
  // Half way from identity to 180 degrees about z: 90 degrees about z.
  EXPECT_LT(
      reading.orientation.angularDistance(Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()))),
      1e-12);
  EXPECT_EQ(oriented.lastTorque(), Eigen::Vector3d(0.0, 0.01, 0.0));
  EXPECT_EQ(reading.position, plain_reading.position);  // the torque moves nothing
  EXPECT_FALSE(plain_reading.has_orientation);
  EXPECT_FALSE(readOrientationScript(MapParameterSource("test: ")).has_value());
  // A zero quaternion in the script is refused, named.
  source.set("orientation_script", table({{0.0, 0.0, 0.0, 0.0, 0.0}}));
  try
  {
    readOrientationScript(source);
    ADD_FAILURE() << "a zero quaternion was taken";
  }
  catch (const InputError& error)
  {
    EXPECT_NE(std::string(error.what()).find("test: orientation_script"), std::string::npos) << error.what();
  }
}

// The interactive hand (setHandTarget, setHandPose): dragged by position only the device
// reports no orientation, its readings the same as before (a 3-DOF finger); once turned
// (setHandPose) every reading carries the last orientation given, also after later
// position-only drags, and over an orientation script; an unusable orientation is ignored and
// its position still taken.
TEST(FakeDevice, AnInteractiveHandIsOrientedOnlyOnceTurned)
{
  const WaypointPath still({{0.0, Eigen::Vector3d::Zero()}});
  FakeDevice dragged(FakeDeviceParams{}, still);
  FakeDevice same(FakeDeviceParams{}, still);
  dragged.setHandTarget(Eigen::Vector3d(0.01, 0.0, 0.02));
  same.setHandTarget(Eigen::Vector3d(0.01, 0.0, 0.02));
  DeviceReading reading;
  for (int i = 0; i <= 500; ++i)
  {
    reading = dragged.update(i * 1e-3, Eigen::Vector3d(0, 0, 1.0));
    const DeviceReading other = same.update(i * 1e-3, Eigen::Vector3d(0, 0, 1.0));
    ASSERT_EQ(reading.position, other.position) << i;
    ASSERT_FALSE(reading.has_orientation) << i;
  }
  EXPECT_NEAR(reading.position.x(), 0.01, 1e-5);
  // Turned 20 degrees about the finger's axis from pulp down (180 degrees about x).
  const Eigen::Quaterniond rolled(Eigen::AngleAxisd(M_PI + 20.0 * M_PI / 180.0, Eigen::Vector3d::UnitX()));
  EXPECT_TRUE(dragged.setHandPose(Eigen::Vector3d(0.0, 0.02, 0.02), rolled));
  reading = dragged.update(0.501, Eigen::Vector3d::Zero());
  ASSERT_TRUE(reading.has_orientation);
  EXPECT_LT(reading.orientation.angularDistance(rolled), 1e-12);
  for (int i = 502; i <= 1500; ++i)
  {
    reading = dragged.update(i * 1e-3, Eigen::Vector3d::Zero());
  }
  EXPECT_NEAR(reading.position.y(), 0.02, 1e-5);  // the pose's position is the hand's
  // A later position-only drag keeps the orientation; a zero or non-finite one is ignored.
  dragged.setHandTarget(Eigen::Vector3d(0.0, 0.0, 0.03));
  dragged.setHandPose(Eigen::Vector3d(0.0, 0.0, 0.03), Eigen::Quaterniond(0, 0, 0, 0));
  dragged.setHandPose(Eigen::Vector3d(0.0, 0.0, 0.03), Eigen::Quaterniond(NAN, 0, 0, 0));
  for (int i = 1501; i <= 2500; ++i)
  {
    reading = dragged.update(i * 1e-3, Eigen::Vector3d::Zero());
  }
  ASSERT_TRUE(reading.has_orientation);
  EXPECT_LT(reading.orientation.angularDistance(rolled), 1e-12);
  EXPECT_NEAR(reading.position.z(), 0.03, 1e-5);
  // Over an orientation script: the hand's orientation wins once given, not before.
  MapParameterSource source("test: ");
  source.set("orientation_script", table({{0.0, 0.0, 1.0, 0.0, 0.0}}));
  FakeDevice scripted(FakeDeviceParams{}, still, readOrientationScript(source));
  scripted.setHandTarget(Eigen::Vector3d::Zero());
  reading = scripted.update(0.0, Eigen::Vector3d::Zero());
  EXPECT_LT(reading.orientation.angularDistance(Eigen::Quaterniond(0, 1, 0, 0)), 1e-12);
  scripted.setHandPose(Eigen::Vector3d::Zero(), rolled);
  reading = scripted.update(0.001, Eigen::Vector3d::Zero());
  EXPECT_LT(reading.orientation.angularDistance(rolled), 1e-12);
}

TEST(FakeDevice, BadParametersAreNamed)
{
  FakeDeviceParams params;
  params.handle_mass = 0.0;
  EXPECT_EQ(validate(params), "parameter 'handle_mass' = 0 is out of range (0, 100] (kg)");
  EXPECT_THROW(FakeDevice(params, WaypointPath({{0.0, Eigen::Vector3d::Zero()}})), InputError);
}
}  // namespace
}  // namespace god_finger

#include "god_finger/devices/replay_device.h"

namespace god_finger
{
namespace
{
TEST(ReplayDevice, FollowsTheTrackAndIgnoresTheForce)
{
  ReplayDevice device(WaypointPath({{0.0, Eigen::Vector3d(0, 0, 0)}, {1.0, Eigen::Vector3d(0.1, 0.2, 0)}}));
  device.setScriptStart(5.0);
  EXPECT_EQ(device.update(4.0, Eigen::Vector3d(100, 0, 0)).position, Eigen::Vector3d::Zero());  // waits
  const DeviceReading middle = device.update(5.5, Eigen::Vector3d(0, 0, -50));
  EXPECT_LT((middle.position - Eigen::Vector3d(0.05, 0.1, 0)).norm(), 1e-15);
  EXPECT_LT((middle.velocity - Eigen::Vector3d(0.1, 0.2, 0)).norm(), 1e-9);
  EXPECT_LT((device.update(7.0, Eigen::Vector3d(NAN, 0, 0)).position - Eigen::Vector3d(0.1, 0.2, 0)).norm(), 1e-15);
}
}  // namespace
}  // namespace god_finger
