// The servo node: device, coupling and physics in one real-time loop (runtime/servo_loop.h),
// with ROS off the hot path. It owns the devices of its interfaces and the world, and
// publishes from a normal-priority thread, which reads the loop's lock-free queues, every
// topic the three-node topology has: per interface NAME, NAME/device/state
// (god_finger/DeviceState, every tick), NAME/device/force (Vector3Stamped, device frame: the
// force commanded), NAME/pose (PoseStamped, world; the identity orientation for a 3-DOF finger,
// which DeviceState's has_orientation says: ros/world_messages.h poseMessage), NAME/feedback (WrenchStamped, the force
// on the hand, world), NAME/proxy (PointStamped), TF world -> NAME_interface; and contact_areas, markers and the TF of
// every body at ~publish_rate, /diagnostics at 1 Hz (the loop's rate, period, latency and step percentiles, overruns;
// WARN or ERROR for a share of overrun ticks on real time: runtime/diagnostic_levels.h, the thresholds as private
// parameters). Services reset_scene and set_contact_model, dynamic_reconfigure of the method and the model, the
// interactive device's marker, and the devices' buttons all reach the loop through its command queue, applied between
// two steps.
//
// One node rather than three nodelets sharing a loop: the loop must own the devices and the
// world together, so the three roles would be one object anyway; one node keeps that object
// and its publishers in one place, and its topics are the three nodes' topics, unchanged.
//
// Time: ~sim_time (default: /use_sim_time) runs the loop on simulated time (deterministic,
// ~real_time_factor, 1 by default, 0 = as fast as it goes) and publishes /clock; otherwise
// the loop runs on the wall clock at ~rate with SCHED_FIFO ~realtime_priority.
//
// Parameters (private): scene (URDF path, required), interfaces ([finger]), the world's
// (interface_parameters.h: rate, solver_iterations, model, r_max, d0, ...), publish_rate (60
// Hz), realtime_priority (80), sim_time, real_time_factor, script_delay (2 s: fake and replay
// scripts start this long after /god_finger_script_epoch, or on simulated time after time 0).
// Per interface, in NAME/: the device (backend and its parameters), its profile and the
// workspace mapping (interface_parameters.h).
#pragma once

#include <ros/node_handle.h>

#include <memory>

namespace god_finger
{
class ServoNode
{
 public:
  // Throws InputError on bad parameters, scene or device, DeviceError when a device fails to
  // start.
  ServoNode(ros::NodeHandle nh, ros::NodeHandle pnh);
  ~ServoNode();
  ServoNode(const ServoNode&) = delete;
  ServoNode& operator=(const ServoNode&) = delete;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
}  // namespace god_finger
