// Parameters shared by the nodes, read in one place each:
//  - the world (the physics node's and the servo node's private parameters);
//  - an interface's (a device's) parameters, all in the interface's namespace NAME/, where
//    interface.launch puts them once: the device profile (config/devices/PROFILE.yaml, the rows
//    of deviceProfileTable()), the backend (`backend`) and its own parameters (each backend's,
//    devices/device_registry.h), and the workspace mapping (the rows of
//    workspaceMappingParameterTable(), workspace_offset [m] and workspace_rotation [x, y, z, w]).
// The driver, the haptic node, the physics node and the servo node all read an interface from
// there, so the spring the hand feels is the one that pulls its proxy.
#pragma once

#include "god_finger/haptics/device_profile.h"
#include "god_finger/haptics/workspace_mapping.h"
#include "god_finger/physics/world_params.h"

#include <ros/node_handle.h>

#include <string>

namespace god_finger
{
// Every row of worldParameterTable(), and the time step from the loop's rate
// (servoLoopParameterTable()). InputError naming the first bad one.
WorldParams readWorldParams(const ros::NodeHandle& pnh);

struct InterfaceConfig
{
  std::string name;
  DeviceProfile profile;
  WorkspaceMappingParams mapping;
};
// `source`: the interface's namespace (NAME/), or, for the driver and the haptic node, their
// private parameters over it (so that `rosrun ... _backend:=falcon` works as for any node).
InterfaceConfig readInterfaceConfig(const ParameterSource& source, const std::string& name);
}  // namespace god_finger
