// Every device backend, by name: the one list the driver node, the servo loop and the tools
// build devices from. Adding a device is a backend in devices/ plus one row in
// src/devices/registry/device_registry.cpp (and CMake, for a vendor library).
//
// Each backend reads and validates its own parameters from a ParameterSource (no ROS), so a
// bad one is an InputError naming it, and a missing vendor library a DeviceError saying what
// to install.
#pragma once

#include "god_finger/devices/driver_bridge.h"
#include "god_finger/devices/haptic_device.h"
#include "god_finger/devices/pose_source.h"
#include "god_finger/haptics/waypoint_path.h"
#include "god_finger/support/parameter_source.h"

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace god_finger
{
struct DeviceContext
{
  // device_max_force (N): the device profile's one limit, coupling.max_force (haptics/device_profile.h).
  DeviceContext(const ParameterSource& source, double device_max_force) : params(source), max_force(device_max_force) {}
  const ParameterSource& params;  // the device's own parameters (the driver's private namespace)
  double max_force;               // N: the device profile's limit (hardware clamps to it as well)
  // When the script's time 0 is played, on update()'s clock (s); NaN: at the first update.
  double script_start = NAN;
  // Replay: reads the recorded device positions of `topic` in the file `bag`; empty where no
  // recording can be read (then backend replay is refused).
  std::function<WaypointPath(const std::string& bag, const std::string& topic)> read_track;
  std::string default_track_topic = "device/state";
  // pose_source: feeds `feed` from the geometry_msgs/PoseArray params.topic (the interface's
  // namespace) or from the TF frames params.frames, stamps converted to now's clock; returns
  // what keeps the subscription alive. Unset where there is no ROS (then pose_source is refused).
  std::function<std::shared_ptr<void>(const PoseSourceParams& params, std::shared_ptr<PoseFeed> feed)> connect_poses;
  // The ROS driver bridges (omni_msgs, ros_geomagic, crtk, ros_falcon; devices/driver_bridge.h):
  // connects `link` to the driver's topics (src/ros/driver_link_ros.h); returns what keeps the
  // connection alive. Unset where there is no ROS (then those backends are refused).
  std::function<std::shared_ptr<void>(const DriverBridgeParams& params, std::shared_ptr<DriverLink> link)>
      connect_driver;
  std::function<double()> now;  // s: the pose source's and the driver links' clock (steadySeconds())
};

struct DeviceBackend
{
  const char* name;
  const char* profile;  // config/devices/PROFILE.yaml: force limit, coupling, workspace (launch/interface.launch
                        // loads it; test/ros/launch_profiles_test.py checks that it does)
  bool simulated;       // needs no hardware (can run on simulated time, in lockstep)
  bool hand_target;     // moved by a hand the user drags (setHandTarget): the nodes add an rviz marker
  std::unique_ptr<HapticDevice> (*make)(const DeviceContext& context);
  // False: an input-only device (a pose source: hand trackers, gloves, mocap); it renders no
  // force, the forces the loop computes for it go nowhere.
  bool renders_force = true;
};

const std::vector<DeviceBackend>& deviceBackends();
// "fake, interactive, replay, falcon, omni, fake_hand, pose_source, omni_msgs, ros_geomagic, crtk,
// ros_falcon".
std::string deviceBackendNames();
// InputError naming `parameter` and the known names when there is no such backend.
const DeviceBackend& findDeviceBackend(const std::string& name, const std::string& parameter);
// Builds (does not start) the device; its script starts at context.script_start.
std::unique_ptr<HapticDevice> makeDevice(const DeviceBackend& backend, const DeviceContext& context);
}  // namespace god_finger
