// The physics node: a GodFingerWorld stepped at a fixed rate in its own thread, for N
// interfaces named by ~interfaces (each a namespace under the node's one).
//
// Per interface NAME: subscribes NAME/interface_pose (god_finger/InterfacePose, frame world; with
// has_orientation, its orientation, the finger frame in the world, makes the interface an
// oriented finger, without it the finger is 3-DOF: ros/world_messages.h), and, until the first
// interface pose, NAME/pose from a recording made before interface_pose (a bag played into it:
// a pose with the all-zero quaternion is a 3-DOF finger's, recordedThreeDofPose); publishes
// NAME/feedback (geometry_msgs/WrenchStamped: the force on the hand and an oriented finger's
// torque, world, every step) and NAME/proxy (geometry_msgs/PointStamped: the god-object, every
// step), NAME/proxy_state (god_finger/ProxyState: the haptic node's local coupling) and
// NAME/physics_energy (god_finger/PortEnergy: the channel's physics port, src/ros/channel_port.h;
// the device port's from NAME/device_energy, both on a `channel NAME` status of /diagnostics).
// Publishes contact_areas (god_finger/ContactAreaArray), markers
// (visualization_msgs/MarkerArray) and the TF of every body (world -> link name) at
// ~publish_rate; /diagnostics at 1 Hz (step rate, overruns: steps that ended past their deadline
// though every pose was in, late_pose_steps: steps taken at the deadline for want of a pose,
// rejected poses; WARN or ERROR for a share of overrun steps, and each channel's for a margin
// beyond its contact credit: runtime/diagnostic_levels.h, the thresholds as private
// parameters). Services:
// reset_scene (std_srvs/Trigger), set_contact_model (god_finger/SetContactModel). A proxy
// appears at an interface's first valid pose.
//
// Parameters (private; checked at start-up, a bad one is an InputError naming it): scene (URDF
// path, required), interfaces (["finger"]), rate (Hz, 1000), publish_rate (Hz, 60), model,
// solver_iterations, the method's r_max, d0, alpha, n_sgo, tau_a, friction, walk, and the
// proxies' proxy_radius and proxy_mass. Each interface's proxy is pulled with its device's coupling
// profile, read from NAME/ (ros/interface_parameters.h), as its haptic node renders it.
#pragma once

#include <ros/node_handle.h>

#include <memory>

namespace god_finger
{
class PhysicsNode
{
 public:
  // Throws InputError on bad parameters or scene.
  PhysicsNode(ros::NodeHandle nh, ros::NodeHandle pnh);
  ~PhysicsNode();
  PhysicsNode(const PhysicsNode&) = delete;
  PhysicsNode& operator=(const PhysicsNode&) = delete;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
}  // namespace god_finger
