// A device's profile (config/devices/NAME.yaml): what the hand can take and how the coupling
// renders for it. Loaded once per interface (into the interface's namespace NAME/ in ROS, by
// launch/interface.launch) and given to everything that renders or simulates that interface:
// the driver's force guard, the haptic node's local coupling, the world's proxy and the servo
// loop.
#pragma once

#include "god_finger/core/force_guard.h"
#include "god_finger/core/parameter_source.h"
#include "god_finger/core/virtual_coupling.h"

namespace god_finger
{
struct DeviceProfile
{
  // coupling.max_force is the device's one force limit: the guard saturates there too.
  CouplingProfile coupling;
  ForceGuardParams guard;
  // m, device frame, from the workspace centre (the device origin): readings beyond it are
  // clamped onto it and the hand feels a wall (core/workspace_bound.h). Scripts stay within it.
  double workspace_radius = 0.5;
};

// The coupling's rows, the guard's and workspace_radius: what config/devices/NAME.yaml may set.
const ParameterTable<DeviceProfile>& deviceProfileTable();

// Every row of deviceProfileTable() that `source` sets (defaults are the fake device's);
// InputError naming the first bad one.
DeviceProfile readDeviceProfile(const ParameterSource& source);
}  // namespace god_finger
