#include "god_finger/haptics/interface_input.h"

#include "god_finger/haptics/orientation_path.h"
#include "god_finger/haptics/workspace_bound.h"

namespace god_finger
{
InterfaceInput::InterfaceInput(const DeviceProfile& profile, const WorkspaceMapping& mapping)
    : profile_(profile), mapping_(mapping)
{
}

InterfaceInputResult InterfaceInput::read(const InterfaceReading& reading)
{
  InterfaceInputResult result;
  // The workspace bound: the proxy never leaves the workspace, the hand feels its wall.
  const WorkspaceBound bound = boundToWorkspace(reading.position, profile_, mapping_);
  const Eigen::Vector3d target = mapping_.toWorld(bound.position);
  if (!target.allFinite() || !reading.velocity.allFinite())
  {
    return result;  // rejected as a whole: no state changes
  }
  result.accepted = true;
  result.target = target;
  result.wall_force = bound.wall_force;
  result.pressed = reading.buttons & ~buttons_;
  buttons_ = reading.buttons;
  if (reading.has_orientation && usableOrientation(reading.orientation))
  {
    device_orientation_ = reading.orientation.normalized();
    world_orientation_ = mapping_.orientationToWorld(device_orientation_);
    oriented_ = true;
    result.orientation = OrientationInput::kUsable;
  }
  else if (reading.has_orientation)
  {
    result.orientation = OrientationInput::kRejected;
  }
  return result;
}
}  // namespace god_finger
