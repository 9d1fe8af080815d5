// The haptic node: between one device driver and the physics, for one interface.
//
// Subscribes device/state (god_finger/DeviceState); publishes interface_pose
// (god_finger/InterfacePose, frame world: the interface position mapped by WorkspaceMapping, and
// a state's orientation mapped by it with has_orientation, or has_orientation false for a device
// that reports none; an unusable orientation is counted, rejected_orientations, and the last
// usable one kept), the physics' input, and the same as pose (geometry_msgs/PoseStamped, the
// identity orientation for a 3-DOF finger: ros/world_messages.h poseMessage) for generic tools,
// and its TF (world -> ~interface_frame). Turns feedback (geometry_msgs/WrenchStamped,
// world) into device/force (geometry_msgs/Vector3Stamped, device frame); with a profile that has
// torque_axes, the feedback's torque (an oriented finger's) into device/torque
// (geometry_msgs/Vector3Stamped, N m, device frame), whatever ~local_coupling.
// With ~local_coupling (the default) the node renders the virtual coupling itself, with the
// device's profile (the one the physics pulls the proxy with, read from the interface's
// namespace), from the freshest device position and the last step's god-object (proxy_state,
// god_finger/ProxyState: the proxy, the target it answered, the step's force and contact
// planes), on every device state, as the servo loop renders between steps
// (runtime/multirate_render.h: the step's god-object while the hand presses into one of its
// contact planes, the hand itself otherwise, so topic latency delays the walls, not free motion,
// and the spring is the hand's own; an older proxy state than the last is ignored; a malformed proxy state is counted,
// rejected_proxy_states, and the last good one kept; one older than ~proxy_timeout, 0.25 s,
// renders nothing, so that the driver's watchdog ramps the force down when the physics dies);
// otherwise it forwards the physics' feedback. Workspace
// mapping: the interface's workspace_scale, force_scale, workspace_offset, workspace_rotation.
// A device position beyond the profile's workspace_radius is clamped before it is mapped and the
// hand feels the workspace wall (haptics/workspace_bound.h), added to every device/force.
// ~model: the physics' initial contact model (where button 0 cycles from).
// Buttons: button 0 cycles the contact model (god_object -> god_finger -> soft_finger), button
// 1 resets the scene (services set_contact_model, reset_scene, resolved in ~physics_namespace).
// Non-finite device states are rejected and counted (diagnostics), never published.
// The channel's device port (src/ros/channel_port.h): the hand's work through the force applied
// counted on every state and sent on device_energy (god_finger/PortEnergy); the physics port's
// packets taken from physics_energy; both on /diagnostics (channel_*), a malformed packet counted.
// The status is WARN or ERROR (runtime/diagnostic_levels.h, thresholds as private parameters)
// while no device state came or the newest is older than device_state_timeout, with the local
// coupling while no proxy state came or the newest is older than proxy_timeout, and for a
// channel margin beyond the profile's passivity_contact_credit.
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
