#include "god_finger/core/device_profile.h"

#include "god_finger/core/input_error.h"

namespace god_finger
{
DeviceProfile readDeviceProfile(const ParameterSource& source)
{
  DeviceProfile profile;
  CouplingProfile& coupling = profile.coupling;
  coupling.max_force = readDouble(source, "max_force", coupling.max_force, 0.0, 1e3, "N", true);
  coupling.stiffness = readDouble(source, "coupling_stiffness", coupling.stiffness, 0.0, 1e5, "N/m", true);
  coupling.damping = readDouble(source, "coupling_damping", coupling.damping, 0.0, 1e3, "N s/m");
  ForceGuardParams& guard = profile.guard;
  guard.max_force = coupling.max_force;
  guard.command_timeout = readDouble(source, "command_timeout", guard.command_timeout, 0.0, 10.0, "s", true);
  guard.ramp_time = readDouble(source, "ramp_time", guard.ramp_time, 0.0, 1.0, "s", true);
  profile.workspace_radius = readDouble(source, "workspace_radius", profile.workspace_radius, 0.0, 10.0, "m", true);
  return profile;
}
}  // namespace god_finger
