#include "servo_setup.h"

#include "bag_track.h"
#include "driver_link_ros.h"
#include "god_finger/devices/device_registry.h"
#include "god_finger/runtime/servo_clock.h"
#include "god_finger/scene/urdf_scene.h"
#include "god_finger/support/input_error.h"
#include "hand_marker.h"
#include "interface_parameters.h"
#include "node_parameters.h"
#include "parameters.h"
#include "pose_feed_ros.h"
#include "scene_parameter.h"

#include <cmath>

namespace god_finger
{
ServoSetup makeServoSetup(const ros::NodeHandle& nh, const ros::NodeHandle& pnh, ServoLoop::Log log)
{
  ServoSetup setup;
  const WorldParams world_params = readWorldParams(pnh);
  ServoLoopParams loop_params = readLoopParams(pnh);
  const NodeParams node_params = readNodeParams(pnh);
  bool use_sim_time = false;
  ros::param::get("/use_sim_time", use_sim_time);
  const bool sim_time = readBool(pnh, "sim_time", use_sim_time);
  loop_params.simulated_time = sim_time;
  loop_params.snapshot_every = std::max(1, static_cast<int>(std::lround(loop_params.rate / node_params.publish_rate)));
  std::string scene_path;
  auto world = loadSceneWorld(pnh, world_params, &scene_path);
  const std::vector<std::string> interface_names = readStringList(pnh, "interfaces", {"finger"});
  std::vector<std::string> names;  // one per finger
  // Simulated devices start their scripts together: on simulated time script_delay after 0,
  // on the wall clock script_delay after the launch's epoch (the loop's clock starts now).
  const double script_start = sim_time ? node_params.script_delay : sharedScriptStart(pnh, 0.0);
  std::vector<ServoInterface> servo_interfaces;
  for (const std::string& name : interface_names)
  {
    ros::NodeHandle interface_nh(nh, name);
    const RosParameterSource device_params(interface_nh);
    const InterfaceConfig config = readInterfaceConfig(device_params, name);
    const std::string backend_name = readString(device_params, "backend", "fake");
    const DeviceBackend& backend = findDeviceBackend(backend_name, device_params.fullName("backend"));
    if (sim_time && !backend.simulated)
    {
      throw InputError("parameter '" + pnh.resolveName("sim_time") + "' is true, but interface '" + name +
                       "' has the hardware backend '" + backend_name +
                       "': a person's hand does not run on simulated time");
    }
    DeviceContext context(device_params, config.profile.coupling.max_force);
    context.script_start = script_start;
    context.read_track = readBagTrack;
    context.default_track_topic = interface_nh.resolveName("device/state");
    context.connect_poses = [interface_nh](const PoseSourceParams& params, std::shared_ptr<PoseFeed> feed)
    { return connectPoseFeed(interface_nh, params, std::move(feed)); };
    const std::string node_name = pnh.getNamespace();
    context.connect_driver =
        [interface_nh, node_name](const DriverBridgeParams& params, std::shared_ptr<DriverLink> link)
    { return connectDriverLink(interface_nh, node_name, params, std::move(link)); };
    context.now = steadySeconds;
    std::unique_ptr<HapticDevice> device = makeDevice(backend, context);
    // A hand (devices/hand_device.h) is one interface per finger, NAME/FINGER, with the
    // interface's profile and mapping; every other device is one.
    std::vector<DeviceFinger> fingers = device->fingers();
    if (fingers.empty())
    {
      fingers.push_back({"", std::move(device)});
    }
    for (DeviceFinger& finger : fingers)
    {
      ServoInterface servo;
      servo.name = finger.name.empty() ? name : name + "/" + finger.name;
      servo.device = std::move(finger.device);
      servo.profile = config.profile;
      servo.mapping = WorkspaceMapping(config.mapping);
      servo_interfaces.push_back(std::move(servo));
      names.push_back(servo_interfaces.back().name);
      setup.backends.push_back(backend_name);
      setup.hand_targets.push_back(backend.hand_target);
      setup.hand_starts.push_back(readVector(device_params, "start", Eigen::Vector3d(0, 0, 0.12)));
    }
  }
  setup.names = names;
  setup.loop = std::make_unique<ServoLoop>(std::move(world), std::move(servo_interfaces), loop_params, log);
  setup.loop->prepare();
  setup.world_params = world_params;
  setup.scene_path = scene_path;
  return setup;
}
}  // namespace god_finger
