// The one list of device backends: names, simulated or not, each backend reading its own
// parameters, unknown names refused with the list, missing vendor libraries named.
#include "god_finger/devices/device_registry.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

namespace god_finger
{
namespace
{
constexpr double kMaxForce = 8.0;  // N: a device profile's limit (the Falcon caps it at 8.9)

TEST(DeviceRegistry, ListsEveryBackendOnce)
{
  EXPECT_EQ(
      deviceBackendNames(),
      "fake, interactive, replay, falcon, omni, fake_hand, pose_source, omni_msgs, ros_geomagic, crtk, ros_falcon");
  EXPECT_TRUE(findDeviceBackend("fake", "backend").simulated);
  EXPECT_FALSE(findDeviceBackend("falcon", "backend").simulated);
  EXPECT_TRUE(findDeviceBackend("interactive", "backend").hand_target);
  EXPECT_FALSE(findDeviceBackend("fake", "backend").hand_target);
  EXPECT_STREQ(findDeviceBackend("replay", "backend").profile, "fake");
  try
  {
    findDeviceBackend("mouse", "/finger/backend");
    FAIL();
  }
  catch (const InputError& error)
  {
    EXPECT_STREQ(error.what(),
                 "parameter '/finger/backend' = 'mouse' is not one of fake, interactive, replay, falcon, omni, "
                 "fake_hand, pose_source, omni_msgs, ros_geomagic, crtk, ros_falcon");
  }
}

TEST(DeviceRegistry, FakeDeviceFollowsItsScriptFromTheSharedStart)
{
  MapParameterSource params("/finger/");
  ParameterValue script;
  script.kind = ParameterValue::Kind::kList;
  script.items.push_back(ParameterValue::of(std::vector<double>{0.0, 0.0, 0.0, 0.1}));
  script.items.push_back(ParameterValue::of(std::vector<double>{1.0, 0.0, 0.0, 0.05}));
  params.set("script", script);
  DeviceContext context(params, kMaxForce);
  context.script_start = 2.0;
  auto device = makeDevice(findDeviceBackend("fake", "backend"), context);
  device->start();
  EXPECT_NEAR(device->update(0.0, Eigen::Vector3d::Zero()).position.z(), 0.1, 1e-12);
  EXPECT_NEAR(device->update(1.9, Eigen::Vector3d::Zero()).position.z(), 0.1, 1e-9);  // waits for its start
  double z = 0.0;
  for (int k = 1901; k <= 4000; ++k)
  {
    z = device->update(k * 1e-3, Eigen::Vector3d::Zero()).position.z();
  }
  EXPECT_NEAR(z, 0.05, 1e-4);
  EXPECT_TRUE(device->setHandTarget(Eigen::Vector3d(0, 0, 0.2)));
  EXPECT_FALSE(device->update(4.001, Eigen::Vector3d::Zero()).has_orientation);
  // The registry's device passes a turned hand on (setHandPose).
  const Eigen::Quaterniond turned(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()));
  EXPECT_TRUE(device->setHandPose(Eigen::Vector3d(0, 0, 0.2), turned));
  const DeviceReading reading = device->update(4.002, Eigen::Vector3d::Zero());
  ASSERT_TRUE(reading.has_orientation);
  EXPECT_LT(reading.orientation.angularDistance(turned), 1e-12);
}

TEST(DeviceRegistry, EachBackendChecksItsOwnParameters)
{
  MapParameterSource params("/finger/");
  params.set("handle_mass", ParameterValue::of(0.0));
  DeviceContext context(params, kMaxForce);
  EXPECT_THROW(makeDevice(findDeviceBackend("fake", "backend"), context), InputError);
  MapParameterSource falcon("/left/");
  falcon.set("index", ParameterValue::ofInteger(20));
  try
  {
    makeDevice(findDeviceBackend("falcon", "backend"), DeviceContext(falcon, kMaxForce));
    FAIL();
  }
  catch (const InputError& error)
  {
    EXPECT_STREQ(error.what(), "parameter '/left/index' = 20 is out of range [0, 15] (count)");
  }
  MapParameterSource replay;
  try
  {
    makeDevice(findDeviceBackend("replay", "backend"), DeviceContext(replay, kMaxForce));
    FAIL();
  }
  catch (const InputError& error)
  {
    EXPECT_STREQ(error.what(), "parameter 'bag' is required by backend 'replay' (a recorded bag)");
  }
#ifndef GOD_FINGER_HAVE_NIFALCON
  MapParameterSource plain;
  EXPECT_THROW(makeDevice(findDeviceBackend("falcon", "backend"), DeviceContext(plain, kMaxForce)), DeviceError);
#endif
}
}  // namespace
}  // namespace god_finger
