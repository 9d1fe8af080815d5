#include "god_finger/haptics/workspace_bound.h"

namespace god_finger
{
WorkspaceBound boundToWorkspace(const Eigen::Vector3d& device_position, const DeviceProfile& profile,
                                const WorkspaceMapping& mapping)
{
  WorkspaceBound bound;
  bound.position = device_position;
  const double distance = device_position.norm();
  if (!device_position.allFinite() || distance <= profile.workspace_radius)
  {
    return bound;
  }
  bound.outside = true;
  bound.position = device_position * (profile.workspace_radius / distance);
  const double stiffness = profile.coupling.stiffness * mapping.params().scale * mapping.params().force_scale;
  bound.wall_force = -stiffness * (device_position - bound.position);
  return bound;
}
}  // namespace god_finger
