// The messages a world snapshot is published as, the same for the physics node and the servo
// node: contact areas (god_finger/ContactAreaArray), markers, and the TF of every body
// (world -> link name). All in frame `world`, SI units. Not real-time: they allocate.
#pragma once

#include "god_finger/ContactAreaArray.h"
#include "god_finger/InterfacePose.h"
#include "god_finger/ProxyState.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/runtime/multirate_render.h"

#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <ros/time.h>
#include <sensor_msgs/JointState.h>
#include <visualization_msgs/MarkerArray.h>

#include <string>
#include <vector>

namespace god_finger
{
// `interface_names[i]` names the world's interface i.
god_finger::ContactAreaArrayPtr contactAreaMessage(const SceneDescription& scene, const WorldSnapshot& world,
                                                   const std::vector<std::string>& interface_names,
                                                   const ros::Time& stamp);
visualization_msgs::MarkerArrayPtr markerMessage(const SceneDescription& scene, const WorldSnapshot& world,
                                                 double proxy_radius, const ros::Time& stamp);
// An interface's feedback (the force on the hand, N) and proxy (m), in `world`.
// The force (N) and, for an oriented finger, the rotational coupling's torque (N m; zero for a
// 3-DOF finger) on the hand, world frame.
geometry_msgs::WrenchStampedPtr feedbackMessage(const ros::Time& stamp, const Eigen::Vector3d& user_force,
                                                const Eigen::Vector3d& user_torque);
// An interface's pose for generic tools (NAME/pose, `world`: rviz, tf2, bags): the device
// mapped into the world (m), and an oriented finger's orientation (the finger frame in the
// world, unit); a 3-DOF finger's (`orientation` null) is the identity. That a finger is 3-DOF is
// said by interfacePoseMessage()'s has_orientation (and DeviceState's), never by this pose.
geometry_msgs::PoseStampedPtr poseMessage(const ros::Time& stamp, const Eigen::Vector3d& position,
                                          const Eigen::Quaterniond* orientation);
// The same pose as the physics takes it in the topic topologies (NAME/interface_pose,
// god_finger/InterfacePose): has_orientation false for a 3-DOF finger (`orientation` null).
god_finger::InterfacePosePtr interfacePoseMessage(const ros::Time& stamp, const Eigen::Vector3d& position,
                                                  const Eigen::Quaterniond* orientation);
// world -> `frame` at the pose (the identity rotation for a 3-DOF finger, as the pose's).
geometry_msgs::TransformStamped interfaceTransform(const geometry_msgs::PoseStamped& pose, const std::string& frame);
// An interface pose's orientation: false for a 3-DOF finger (has_orientation false); else
// `orientation` is the message's as it is (GodFingerWorld::setInterfaceTarget normalises it, or
// ignores and counts it when unusable).
bool poseOrientation(const god_finger::InterfacePose& pose, Eigen::Quaterniond* orientation);
// Whether a NAME/pose is a 3-DOF finger's as the nodes sent it before NAME/interface_pose (the
// all-zero quaternion, "no orientation"): what a recording made then holds, which the physics
// node still takes (a bag played into it); a pose with any other orientation is not one.
bool recordedThreeDofPose(const geometry_msgs::Pose& pose);
geometry_msgs::PointStampedPtr proxyMessage(const ros::Time& stamp, const Eigen::Vector3d& proxy_position);
// One step's god-object for the haptic node's local coupling (NAME/proxy_state,
// god_finger/ProxyState, `world`): the proxy, the target the step took, its force, its contacts'
// normals (the first MultirateStep::kMaxPlanes) and a soft contact's stiffness (0: none).
god_finger::ProxyStatePtr proxyStateMessage(const ros::Time& stamp, const InterfaceState& state);
// The message as the renderer's step, `lag` ticks old. False, `step` untouched, for a message
// with a non-finite value, a plane that is not unit length (within 1e-6), more than kMaxPlanes
// planes or a negative stiffness.
bool multirateStep(const god_finger::ProxyState& message, long lag, MultirateStep* step);
// The scene's joints (articulated objects) as sensor_msgs/JointState: name, position (rad or m)
// and velocity per joint, in the scene's order (joint_measure.h), no effort.
sensor_msgs::JointStatePtr jointStateMessage(const SceneDescription& scene, const WorldSnapshot& world,
                                             const ros::Time& stamp);
std::vector<geometry_msgs::TransformStamped> bodyTransforms(const SceneDescription& scene, const WorldSnapshot& world,
                                                            const ros::Time& stamp);
}  // namespace god_finger
