// The device driver node: one haptic device served at ~rate (1 kHz) in its own thread.
//
// Publishes device/state (god_finger/DeviceState, with the reading's orientation when it has
// one, and the torque applied) every tick; subscribes device/torque (geometry_msgs/Vector3Stamped,
// N m, device frame: kept on the profile's torque_axes and saturated at max_torque, given to the
// device scaled by the guard's ForceGuard::scale, not at all once older than command_timeout)
// and device/force
// (geometry_msgs/Vector3Stamped, device frame, N). Every force goes through a ForceGuard:
// saturated to the profile's max_force, rejected (and counted) when not finite, ramped to zero
// within ramp_time when no command came for command_timeout, ramped in over soft_start at
// start and resume, rate- and budget-limited (haptics/force_guard.h). Service stop_force
// (std_srvs/SetBool, the interface's namespace): true zeroes this device's force at once, false
// resumes it with the soft start. /diagnostics at 1 Hz, a status named "BACKEND device" for the
// backend's name in the registry: rate, overruns, rejected and saturated commands, watchdog
// state, stop, budget-limited outputs; WARN or ERROR for a share of overrun ticks
// (runtime/diagnostic_levels.h, the thresholds set here as private parameters) and ERROR while
// the device is lost (a ROS driver older than its stale_timeout).
//
// The device, its profile and parameters are the interface's, in the node's namespace
// (ros/interface_parameters.h): backend (devices/device_registry.h: fake, interactive, replay,
// falcon, omni) and the backend's own parameters. Private: rate (Hz), realtime_priority,
// frame, script_delay, the diagnostics' thresholds (overrun_warn_share, overrun_error_share).
#pragma once

#include <ros/node_handle.h>

#include <memory>

namespace god_finger
{
class DeviceDriverNode
{
 public:
  // Throws InputError on bad parameters, DeviceError when the backend cannot start.
  DeviceDriverNode(ros::NodeHandle nh, ros::NodeHandle pnh);
  ~DeviceDriverNode();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
}  // namespace god_finger
