// The god-object message the haptic node's local coupling renders against (NAME/proxy_state,
// src/ros/world_messages.h): a step's state goes out and comes back as the renderer's step, and
// a malformed message (a non-finite value, a plane that is not unit length, too many planes, a
// negative stiffness) is refused whole, the caller keeping its last good step. An interface's
// pose: the identity orientation for a 3-DOF finger on NAME/pose (tools take it), its 3-DOF
// nature in NAME/interface_pose's has_orientation, and a recording's all-zero quaternion still
// read as a 3-DOF finger.
#include "world_messages.h"

#include <gtest/gtest.h>

#include <limits>

namespace god_finger
{
namespace
{
InterfaceState pressedOnTwoFaces()
{
  InterfaceState state;
  state.proxy_position = Eigen::Vector3d(0.1, 0.0, 0.004);
  state.interface_position = Eigen::Vector3d(0.1, 0.002, -0.003);
  state.user_force = Eigen::Vector3d(0.0, -1.6, 5.6);
  state.contact_count = 2;
  state.contacts[0].normal = Eigen::Vector3d::UnitZ();
  state.contacts[1].normal = -Eigen::Vector3d::UnitY();
  return state;
}

TEST(WorldMessages, AProxyStateComesBackAsTheStepItWas)
{
  const InterfaceState state = pressedOnTwoFaces();
  const god_finger::ProxyStatePtr message = proxyStateMessage(ros::Time(12.5), state);
  EXPECT_EQ(message->header.stamp, ros::Time(12.5));
  EXPECT_EQ(message->header.frame_id, "world");
  EXPECT_EQ(message->contact_stiffness, 0.0);  // rigid
  MultirateStep step;
  ASSERT_TRUE(multirateStep(*message, 1, &step));
  EXPECT_EQ(step.proxy_position, state.proxy_position);
  EXPECT_EQ(step.step_target, state.interface_position);
  EXPECT_EQ(step.user_force, state.user_force);
  EXPECT_EQ(step.lag, 1);
  ASSERT_EQ(step.plane_count, 2);
  EXPECT_EQ(step.plane_normals[0], Eigen::Vector3d::UnitZ());
  EXPECT_EQ(step.plane_normals[1], -Eigen::Vector3d::UnitY());
  EXPECT_EQ(step.contact_stiffness, std::numeric_limits<double>::infinity());
  // The god-object it predicts for a hand pressing into a face: the step's; out of both: the hand.
  EXPECT_EQ(predictedProxy(step, Eigen::Vector3d(0.12, 0.003, -0.01)), state.proxy_position);
  EXPECT_EQ(predictedProxy(step, Eigen::Vector3d(0.12, -0.003, 0.01)), Eigen::Vector3d(0.12, -0.003, 0.01));

  InterfaceState soft = state;
  soft.contact_count = 1;
  soft.contact_stiffness = 1200.0;
  soft.contact_normal = Eigen::Vector3d::UnitZ();
  ASSERT_TRUE(multirateStep(*proxyStateMessage(ros::Time(1.0), soft), 2, &step));
  EXPECT_EQ(step.contact_stiffness, 1200.0);
  EXPECT_EQ(step.contact_normal, Eigen::Vector3d::UnitZ());
  EXPECT_EQ(step.plane_count, 1);
}

TEST(WorldMessages, AMalformedProxyStateIsRefusedWhole)
{
  const god_finger::ProxyStatePtr good = proxyStateMessage(ros::Time(1.0), pressedOnTwoFaces());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::pair<const char*, god_finger::ProxyState>> bad;
  bad.emplace_back("NaN proxy", *good);
  bad.back().second.proxy.x = nan;
  bad.emplace_back("infinite target", *good);
  bad.back().second.target.z = std::numeric_limits<double>::infinity();
  bad.emplace_back("NaN force", *good);
  bad.back().second.force.y = nan;
  bad.emplace_back("a plane of length 2", *good);
  bad.back().second.planes[0].z = 2.0;
  bad.emplace_back("a zero plane", *good);
  bad.back().second.planes[1].y = 0.0;
  bad.emplace_back("five planes", *good);
  bad.back().second.planes.resize(5, good->planes[0]);
  bad.emplace_back("negative stiffness", *good);
  bad.back().second.contact_stiffness = -1.0;
  bad.emplace_back("NaN stiffness", *good);
  bad.back().second.contact_stiffness = nan;
  bad.emplace_back("soft with a zero normal", *good);
  bad.back().second.contact_stiffness = 500.0;
  bad.back().second.contact_normal.z = 0.0;
  MultirateStep kept;
  ASSERT_TRUE(multirateStep(*good, 1, &kept));
  const MultirateStep before = kept;
  for (const auto& [what, message] : bad)
  {
    EXPECT_FALSE(multirateStep(message, 1, &kept)) << what;
    EXPECT_EQ(kept.proxy_position, before.proxy_position) << what;  // untouched
    EXPECT_EQ(kept.plane_count, before.plane_count) << what;
  }
}

TEST(WorldMessages, AThreeDofFingersPoseIsTheIdentityAndItsInterfacePoseSaysSo)
{
  const Eigen::Vector3d position(0.01, -0.02, 0.075);
  const geometry_msgs::PoseStampedPtr pose = poseMessage(ros::Time(3.0), position, nullptr);
  EXPECT_EQ(pose->header.frame_id, "world");
  EXPECT_EQ(pose->pose.position.z, 0.075);
  // The identity: a unit quaternion tf2 and rviz take (the all-zero one they reject).
  EXPECT_EQ(pose->pose.orientation.w, 1.0);
  EXPECT_EQ(pose->pose.orientation.x, 0.0);
  EXPECT_EQ(pose->pose.orientation.y, 0.0);
  EXPECT_EQ(pose->pose.orientation.z, 0.0);
  const geometry_msgs::TransformStamped transform = interfaceTransform(*pose, "finger_interface");
  EXPECT_EQ(transform.child_frame_id, "finger_interface");
  EXPECT_EQ(transform.transform.rotation.w, 1.0);
  EXPECT_EQ(transform.transform.translation.y, -0.02);

  const god_finger::InterfacePosePtr physics = interfacePoseMessage(ros::Time(3.0), position, nullptr);
  EXPECT_FALSE(physics->has_orientation);
  EXPECT_EQ(physics->pose.orientation.w, 1.0);
  EXPECT_EQ(physics->header.stamp, ros::Time(3.0));
  Eigen::Quaterniond orientation(0.5, 0.5, 0.5, 0.5);
  EXPECT_FALSE(poseOrientation(*physics, &orientation));
  EXPECT_EQ(orientation.w(), 0.5);  // untouched
  // NAME/pose is a tool's copy: its identity is no recording's 3-DOF pose (the physics takes
  // the interface pose instead).
  EXPECT_FALSE(recordedThreeDofPose(pose->pose));
}

TEST(WorldMessages, AnOrientedFingersPoseCarriesItsOrientation)
{
  // Pulp down, rolled 20 degrees about the finger's axis.
  const Eigen::Quaterniond finger =
      Eigen::Quaterniond(0.0, 1.0, 0.0, 0.0) * Eigen::Quaterniond(Eigen::AngleAxisd(0.349, Eigen::Vector3d::UnitX()));
  const geometry_msgs::PoseStampedPtr pose = poseMessage(ros::Time(1.0), Eigen::Vector3d::Zero(), &finger);
  EXPECT_EQ(pose->pose.orientation.w, finger.w());
  EXPECT_EQ(pose->pose.orientation.x, finger.x());
  EXPECT_EQ(interfaceTransform(*pose, "f").transform.rotation.x, finger.x());
  const god_finger::InterfacePosePtr physics = interfacePoseMessage(ros::Time(1.0), Eigen::Vector3d::Zero(), &finger);
  EXPECT_TRUE(physics->has_orientation);
  Eigen::Quaterniond read = Eigen::Quaterniond::Identity();
  ASSERT_TRUE(poseOrientation(*physics, &read));
  EXPECT_EQ(read.coeffs(), finger.coeffs());
  // Oriented at exactly the identity (pulp up) is still oriented: the flag says it, not the value.
  const Eigen::Quaterniond identity = Eigen::Quaterniond::Identity();
  EXPECT_TRUE(interfacePoseMessage(ros::Time(1.0), Eigen::Vector3d::Zero(), &identity)->has_orientation);
}

TEST(WorldMessages, ARecordingsAllZeroQuaternionIsAThreeDofFinger)
{
  // NAME/pose as the nodes sent it before NAME/interface_pose: a 3-DOF finger's orientation
  // all zero (what an older bag holds).
  geometry_msgs::Pose recorded;
  recorded.position.z = 0.1;
  recorded.orientation.w = 0.0;
  EXPECT_TRUE(recordedThreeDofPose(recorded));
  recorded.orientation.x = 1.0;  // an oriented finger's, pulp down: not a 3-DOF one
  EXPECT_FALSE(recordedThreeDofPose(recorded));
}
}  // namespace
}  // namespace god_finger
