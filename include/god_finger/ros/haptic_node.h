// The haptic node: between one device driver and the physics, for one interface.
//
// Subscribes device/state (god_finger/DeviceState); publishes pose (geometry_msgs/PoseStamped,
// frame world: the interface position mapped by WorkspaceMapping, and a state's orientation
// mapped by it, or the all-zero quaternion for a device that reports none: ros/world_messages.h
// poseMessage; an unusable orientation is counted, rejected_orientations, and the last usable
// one kept) and its TF (world -> ~interface_frame). Turns feedback (geometry_msgs/WrenchStamped,
// world) into device/force (geometry_msgs/Vector3Stamped, device frame); with a profile that has
// torque_axes, the feedback's torque (an oriented finger's) into device/torque
// (geometry_msgs/Vector3Stamped, N m, device frame), whatever ~local_coupling.
// With ~local_coupling (the default) the node renders the virtual coupling itself, with the
// device's profile (the one the physics pulls the proxy with, read from the interface's
// namespace), from the freshest device position and the last god-object position (proxy,
// geometry_msgs/PointStamped), on every device state (multi-rate rendering: topic latency then
// delays the proxy, not the spring; a proxy older than ~proxy_timeout, 0.25 s, renders
// nothing, so that the driver's watchdog ramps the force down when the physics dies);
// otherwise it forwards the physics' feedback. Workspace
// mapping: the interface's workspace_scale, force_scale, workspace_offset, workspace_rotation.
// A device position beyond the profile's workspace_radius is clamped before it is mapped and the
// hand feels the workspace wall (haptics/workspace_bound.h), added to every device/force.
// ~model: the physics' initial contact model (where button 0 cycles from).
// Buttons: button 0 cycles the contact model (god_object -> god_finger -> soft_finger), button
// 1 resets the scene (services set_contact_model, reset_scene, resolved in ~physics_namespace).
// Non-finite device states are rejected and counted (diagnostics), never published.
#pragma once

#include <ros/node_handle.h>

#include <memory>

namespace god_finger
{
class HapticNode
{
 public:
  // Throws InputError on bad parameters.
  HapticNode(ros::NodeHandle nh, ros::NodeHandle pnh);
  ~HapticNode();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
}  // namespace god_finger
