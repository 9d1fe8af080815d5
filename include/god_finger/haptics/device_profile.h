// A device's profile (config/devices/NAME.yaml): what the hand can take and how the coupling
// renders for it. Loaded once per interface (into the interface's namespace NAME/ in ROS, by
// launch/interface.launch) and given to everything that renders or simulates that interface:
// the driver's force guard, the haptic node's local coupling, the world's proxy and the servo
// loop.
#pragma once

#include "god_finger/haptics/force_guard.h"
#include "god_finger/haptics/passivity_controller.h"
#include "god_finger/haptics/virtual_coupling.h"
#include "god_finger/support/parameter_source.h"

#include <string>

namespace god_finger
{
struct DeviceProfile
{
  // coupling.max_force is the device's one force limit: the guard saturates there too.
  CouplingProfile coupling;
  ForceGuardParams guard;
  // The passivity observer and controller at the device's port (the device driver's, after the
  // guard): the loop behind it (the link, the physics) kept passive.
  PassivityParams passivity;
  // m, device frame, from the workspace centre (the device origin): readings beyond it are
  // clamped onto it and the hand feels a wall (haptics/workspace_bound.h). Scripts stay within it.
  double workspace_radius = 0.5;
  // The device-frame axes on which the device renders torque (an oriented finger's rotational
  // coupling, physics/oriented_finger.h): a bit mask, bit 0 x, bit 1 y, bit 2 z (kTorqueX...).
  // 0 (none, every force-only device: the Omni/Touch, the Falcon): the device is sent no
  // torque. The servo loop zeroes the other axes, then saturates the torque's length at
  // max_torque.
  unsigned torque_axes = 0;
  double max_torque = 0.0;  // N m: the torque's length never exceeds it
};

constexpr unsigned kTorqueX = 1u;
constexpr unsigned kTorqueY = 2u;
constexpr unsigned kTorqueZ = 4u;
// "none", "x", "y", "z", "xy", "xz", "yz", "xyz" (the row's choices, in that order).
std::string torqueAxesName(unsigned axes);
// False for a name not among them.
bool parseTorqueAxes(const std::string& name, unsigned* axes);

// `torque` (N m, device frame) with the profile's other axes zeroed and its length saturated at
// max_torque: what the device may render. Real-time safe.
Eigen::Vector3d renderableTorque(const DeviceProfile& profile, const Eigen::Vector3d& torque);

// The coupling's rows, the guard's, the passivity controller's, workspace_radius, torque_axes and
// max_torque: what config/devices/NAME.yaml may set.
const ParameterTable<DeviceProfile>& deviceProfileTable();

// Every row of deviceProfileTable() that `source` sets (defaults are the fake device's);
// InputError naming the first bad one.
DeviceProfile readDeviceProfile(const ParameterSource& source);
}  // namespace god_finger
