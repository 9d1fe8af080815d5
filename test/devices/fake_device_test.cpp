// The fake device against analytic answers: it follows its scripted hand, a constant force
// deflects it by F / grip stiffness, and bad parameters are named.
#include "god_finger/devices/fake_device.h"
#include "god_finger/core/input_error.h"

#include <gtest/gtest.h>

namespace god_finger
{
namespace
{
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
