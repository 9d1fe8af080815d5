// The device's workspace bound (the profile's workspace_radius), enforced in one place for every
// loop that maps a device into the world (the servo loop, the haptic node): a reading beyond the
// radius is clamped onto the sphere before it is mapped (the proxy never leaves the workspace),
// and the hand feels a wall pushing it back in, a spring with the coupling's stiffness as the
// device feels it through the mapping:
//   p_c = p                    if |p| <= R,   else  R p / |p|
//   F_wall = -k_c scale force_scale (p - p_c)
// Device frame (origin at the workspace centre, the HapticDevice convention), m and N; k_c is
// the coupling's stiffness (N/m, world), scale and force_scale the mapping's. F_wall is added to
// the coupling's force (mapped to the device) before the ForceGuard, which saturates the sum.
// Inside the workspace p_c = p exactly and F_wall = 0. Real-time safe (no allocation).
#pragma once

#include "god_finger/haptics/device_profile.h"
#include "god_finger/haptics/workspace_mapping.h"

#include <Eigen/Core>

namespace god_finger
{
struct WorkspaceBound
{
  Eigen::Vector3d position = Eigen::Vector3d::Zero();    // m, device frame: p_c, within the radius
  Eigen::Vector3d wall_force = Eigen::Vector3d::Zero();  // N, device frame: on the hand
  bool outside = false;                                  // |p| > R
};

// A non-finite position is returned as it is (the caller rejects it) with no force.
WorkspaceBound boundToWorkspace(const Eigen::Vector3d& device_position, const DeviceProfile& profile,
                                const WorkspaceMapping& mapping);
}  // namespace god_finger
