// Hands in the device registry: fake_hand and pose_source are input only (their rows say they
// render no force), carry one device per finger, read their parameters with clear errors;
// a pose source without a pose subscriber (no ROS) is refused.
#include "god_finger/devices/device_registry.h"
#include "god_finger/devices/fake_hand.h"
#include "god_finger/devices/pose_source.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

namespace god_finger
{
namespace
{
constexpr double kMaxForce = 20.0;  // N: the fake profile's

std::string errorOf(const std::string& backend, const MapParameterSource& params, bool with_ros = false)
{
  DeviceContext context(params, kMaxForce);
  if (with_ros)
  {
    context.connect_poses = [](const PoseSourceParams&, std::shared_ptr<PoseFeed>) { return std::shared_ptr<void>(); };
    context.now = []() { return 0.0; };
  }
  try
  {
    makeDevice(findDeviceBackend(backend, "backend"), context);
  }
  catch (const InputError& error)
  {
    return error.what();
  }
  return "";
}

TEST(HandDevices, AreInputOnlyAndCarryOneDevicePerFinger)
{
  EXPECT_FALSE(findDeviceBackend("fake_hand", "backend").renders_force);
  EXPECT_FALSE(findDeviceBackend("pose_source", "backend").renders_force);
  EXPECT_TRUE(findDeviceBackend("fake", "backend").renders_force);
  EXPECT_TRUE(findDeviceBackend("fake_hand", "backend").simulated);
  EXPECT_FALSE(findDeviceBackend("pose_source", "backend").simulated);

  MapParameterSource params("/hand/");
  params.set("fingers", ParameterValue::ofInteger(3));
  DeviceContext context(params, kMaxForce);
  auto hand = makeDevice(findDeviceBackend("fake_hand", "backend"), context);
  std::vector<DeviceFinger> fingers = hand->fingers();
  ASSERT_EQ(fingers.size(), 4u);
  EXPECT_EQ(fingers[0].name, "thumb");
  EXPECT_EQ(fingers[3].name, "ring");
  EXPECT_THROW(hand->update(0.0, Eigen::Vector3d::Zero()), DeviceError);  // the loop runs its fingers
  for (DeviceFinger& finger : fingers)
  {
    finger.device->start();
  }
  // Script time 0: open, 7 cm from the mug's axis, 5 cm up; the thumb on +y.
  hand->setScriptStart(0.0);
  const DeviceReading thumb = fingers[0].device->update(0.0, Eigen::Vector3d(5, 5, 5));
  EXPECT_NEAR(thumb.position.y(), 0.07, 1e-12);
  EXPECT_NEAR(thumb.position.z(), 0.05, 1e-12);
  EXPECT_TRUE(thumb.tracked);
  // Closed at 1 s: the fingers 3.3 cm from the axis.
  const DeviceReading index = fingers[1].device->update(1.0, Eigen::Vector3d::Zero());
  EXPECT_NEAR(index.position.head<2>().norm(), 0.033, 1e-12);
  EXPECT_LT(index.position.y(), 0.0);
}

// The fake hand's fingertips are oriented (6-DOF) fingers as a hand holds a mug: the pulp (z)
// towards the axis tilted up by finger_pitch, the tip (x) down, the body (-x) leaning out; the
// same through the script. `orientation: none` gives positions only.
TEST(HandDevices, TheFakeHandsFingersHoldThePulpTowardsTheAxis)
{
  for (const double pitch : {0.0, 0.5, 1.2})
  {
    SCOPED_TRACE(pitch);
    MapParameterSource params("/hand/");
    params.set("finger_pitch", ParameterValue::of(pitch));
    DeviceContext context(params, kMaxForce);
    auto hand = makeDevice(findDeviceBackend("fake_hand", "backend"), context);
    std::vector<DeviceFinger> fingers = hand->fingers();
    ASSERT_EQ(fingers.size(), 3u);
    hand->setScriptStart(0.0);
    for (DeviceFinger& finger : fingers)
    {
      finger.device->start();
      for (const double t : {0.0, 1.0, 3.0})
      {
        const DeviceReading reading = finger.device->update(t, Eigen::Vector3d::Zero());
        ASSERT_TRUE(reading.has_orientation);
        Eigen::Vector3d out = reading.position - Eigen::Vector3d(0.0, 0.0, reading.position.z());
        out.normalize();
        const Eigen::Vector3d tip = reading.orientation * Eigen::Vector3d::UnitX();
        const Eigen::Vector3d pulp = reading.orientation * Eigen::Vector3d::UnitZ();
        EXPECT_NEAR(pulp.dot(-out), std::cos(pitch), 1e-12);
        EXPECT_NEAR(pulp.z(), std::sin(pitch), 1e-12);
        EXPECT_NEAR(tip.z(), -std::cos(pitch), 1e-12);
        EXPECT_NEAR(tip.dot(out), -std::sin(pitch), 1e-12);  // the body behind the tip: out
        EXPECT_NEAR(reading.orientation.norm(), 1.0, 1e-12);
      }
    }
  }
  MapParameterSource params("/hand/");
  params.set("orientation", ParameterValue::of(std::string("none")));
  DeviceContext context(params, kMaxForce);
  auto hand = makeDevice(findDeviceBackend("fake_hand", "backend"), context);
  std::vector<DeviceFinger> fingers = hand->fingers();
  fingers[1].device->start();
  EXPECT_FALSE(fingers[1].device->update(0.5, Eigen::Vector3d::Zero()).has_orientation);
  MapParameterSource bad("/hand/");
  bad.set("orientation", ParameterValue::of(std::string("pulp_out")));
  EXPECT_NE(errorOf("fake_hand", bad).find("/hand/orientation"), std::string::npos) << errorOf("fake_hand", bad);
}

// The wrist turn: held up, every fingertip goes round the grasp's axis on its arc (the same
// distance from it throughout) and its orientation turns with it, by wrist_turn at 4.2 s; it is
// back where it started, unturned, at 5.8 s.
TEST(HandDevices, TheFakeHandsWristTurnsEveryFingerAboutTheAxis)
{
  MapParameterSource params("/hand/");
  params.set("wrist_turn", ParameterValue::of(0.5));
  DeviceContext context(params, kMaxForce);
  auto hand = makeDevice(findDeviceBackend("fake_hand", "backend"), context);
  std::vector<DeviceFinger> fingers = hand->fingers();
  hand->setScriptStart(0.0);
  const Eigen::Vector3d axis(0.0, 0.0, 0.05 + 0.1);  // grasp_center, lifted by `lift`
  const Eigen::AngleAxisd turn(0.5, Eigen::Vector3d::UnitZ());
  for (DeviceFinger& finger : fingers)
  {
    finger.device->start();
    const DeviceReading start = finger.device->update(0.0, Eigen::Vector3d::Zero());
    const DeviceReading held = finger.device->update(3.5, Eigen::Vector3d::Zero());
    const double radius = (held.position - axis).head<2>().norm();
    for (double t = 3.5; t <= 4.2; t += 0.01)
    {
      const DeviceReading moving = finger.device->update(t, Eigen::Vector3d::Zero());
      EXPECT_NEAR((moving.position - axis).head<2>().norm(), radius, 2e-5) << t;  // 8 chords of the arc
      EXPECT_NEAR(moving.position.z(), axis.z(), 1e-12);
    }
    const DeviceReading turned = finger.device->update(4.2, Eigen::Vector3d::Zero());
    EXPECT_LT((turned.position - (axis + turn * (held.position - axis))).norm(), 1e-12);
    EXPECT_LT(turned.orientation.angularDistance(Eigen::Quaterniond(turn) * held.orientation), 1e-12);
    EXPECT_LT(finger.device->update(4.5, Eigen::Vector3d::Zero()).orientation.angularDistance(turned.orientation),
              1e-12);
    const DeviceReading lowered = finger.device->update(5.8, Eigen::Vector3d::Zero());
    EXPECT_LT((lowered.position - start.position).norm(), 1e-12);
    EXPECT_LT(lowered.orientation.angularDistance(start.orientation), 1e-12);
  }
  MapParameterSource bad("/hand/");
  bad.set("wrist_turn", ParameterValue::of(2.0));
  EXPECT_NE(errorOf("fake_hand", bad).find("/hand/wrist_turn"), std::string::npos) << errorOf("fake_hand", bad);
}

TEST(HandDevices, CheckTheirParameters)
{
  MapParameterSource five("/hand/");
  five.set("fingers", ParameterValue::ofInteger(5));
  EXPECT_EQ(errorOf("fake_hand", five), "parameter '/hand/fingers' = 5 is out of range [2, 4] (count)");
  MapParameterSource low("/hand/");
  low.set("lift", ParameterValue::of(-0.01));
  EXPECT_EQ(errorOf("fake_hand", low), "parameter '/hand/lift' = -0.01 is out of range [0, 0.5] (m)");
  MapParameterSource text("/hand/");
  text.set("grasp_radius", ParameterValue::of(std::string("wide")));
  EXPECT_EQ(errorOf("fake_hand", text), "parameter '/hand/grasp_radius' must be a number (m)");
  MapParameterSource shut("/hand/");
  shut.set("open_radius", ParameterValue::of(0.02));
  EXPECT_EQ(errorOf("fake_hand", shut),
            "parameter '/hand/open_radius' (0.02 m) must exceed '/hand/grasp_radius' (0.033 m): the hand "
            "opens wider than it closes");
  MapParameterSource cycle("/hand/");
  cycle.set("cycle", ParameterValue::of(2.0));
  EXPECT_EQ(errorOf("fake_hand", cycle),
            "parameter '/hand/cycle' (2 s) must be 0 (grasp once) or at least the grasp's 5.8 s");

  MapParameterSource none("/hand/");
  EXPECT_EQ(errorOf("pose_source", none),
            "backend 'pose_source' needs a pose subscriber, which this program does not have (run it with "
            "topology:=servo)");
  EXPECT_EQ(errorOf("pose_source", none, true), "");
  MapParameterSource twice("/hand/");
  twice.set("fingers", ParameterValue::of(std::vector<std::string>{"thumb", "thumb"}));
  EXPECT_EQ(errorOf("pose_source", twice, true),
            "parameter '/hand/fingers': finger 1 'thumb' must be a unique non-empty name without '/' or spaces");
  MapParameterSource frames("/hand/");
  frames.set("frames", ParameterValue::of(std::vector<std::string>{"thumb_tip"}));
  EXPECT_EQ(errorOf("pose_source", frames, true),
            "parameter '/hand/frames' must list one TF frame per finger (3), not 1");
  MapParameterSource timeout("/hand/");
  timeout.set("pose_timeout", ParameterValue::of(0.0));
  EXPECT_EQ(errorOf("pose_source", timeout, true), "parameter '/hand/pose_timeout' = 0 is out of range (0, 10] (s)");
  MapParameterSource rate("/hand/");
  rate.set("poll_rate", ParameterValue::of(20000.0));
  EXPECT_EQ(errorOf("pose_source", rate, true), "parameter '/hand/poll_rate' = 20000 is out of range (0, 10000] (Hz)");
}

// The tables' rows read what they name: a value set through the source lands in its member,
// and the defaults (the structs' initialisers) are inside the ranges.
TEST(HandDevices, ParameterTablesReadTheirMembers)
{
  EXPECT_EQ(validateRows(fakeHandParameterTable(), FakeHandParams()), "");
  EXPECT_EQ(validateRows(poseSourceParameterTable(), PoseSourceParams()), "");
  MapParameterSource hand("/hand/");
  hand.set("fingers", ParameterValue::ofInteger(3));
  hand.set("lift", ParameterValue::of(0.12));
  hand.set("cycle", ParameterValue::of(8.0));
  const FakeHandParams fake = readFakeHandParams(hand);
  EXPECT_EQ(fake.fingers, 3);
  EXPECT_DOUBLE_EQ(fake.lift, 0.12);
  EXPECT_DOUBLE_EQ(fake.cycle, 8.0);
  EXPECT_DOUBLE_EQ(fake.grasp_radius, 0.033);
  MapParameterSource tracker("/hand/");
  tracker.set("pose_timeout", ParameterValue::of(0.25));
  tracker.set("poll_rate", ParameterValue::of(200.0));
  const PoseSourceParams poses = readPoseSourceParams(tracker);
  EXPECT_DOUBLE_EQ(poses.pose_timeout, 0.25);
  EXPECT_DOUBLE_EQ(poses.poll_rate, 200.0);
}
}  // namespace
}  // namespace god_finger
