// A device's profile (config/devices/NAME.yaml): what the hand can take and how the coupling
// renders for it. Loaded once per interface (under the interface's `profile/` namespace in
// ROS) and given to everything that renders or simulates that interface: the driver's force
// guard, the haptic node's local coupling, the world's proxy and the servo loop.
#pragma once

#include "god_finger/core/force_guard.h"
#include "god_finger/core/parameter_source.h"
#include "god_finger/core/virtual_coupling.h"

namespace god_finger
{
struct DeviceProfile
{
  // coupling.max_force is the device's force limit too (guard.max_force is set equal to it).
  CouplingProfile coupling;
  ForceGuardParams guard;
  double workspace_radius = 0.15;  // m: the workspace the scripts stay within
};

// The coupling's rows, the guard's and workspace_radius: what config/devices/NAME.yaml may set.
const ParameterTable<DeviceProfile>& deviceProfileTable();

// Every row of deviceProfileTable() that `source` sets (defaults are the fake device's);
// InputError naming the first bad one.
DeviceProfile readDeviceProfile(const ParameterSource& source);
}  // namespace god_finger
