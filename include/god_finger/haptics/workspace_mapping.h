// From a haptic device's workspace to the world and back.
//
// Position: p_world = offset + scale * R p_device (device frame: the device's own axes turned
// to REP-103 by its backend, metres). Force: f_device = force_scale * R^T f_world. With
// force_scale = scale the mapping is passive (the work done in the world equals the work
// done on the hand); the default 1 renders world forces as they are and leaves the device's
// stiffness at k_world / scale. Orientation (an oriented finger's, physics/oriented_finger.h):
// q_world = R q_device, not scaled; so torque maps by the rotation alone, tau_device = R^T
// tau_world (angles are not scaled: that is passive). Invariant: R is a rotation (orthonormal, det +1).
#pragma once

#include "god_finger/support/parameter_table.h"

#include <Eigen/Geometry>
#include <string>

namespace god_finger
{
struct WorkspaceMappingParams
{
  double scale = 1.0;                                            // world metres per device metre
  double force_scale = 1.0;                                      // device newtons per world newton
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();              // m, world position of the device origin
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  // device axes in the world
};
// workspace_scale, force_scale (offset and rotation are vectors, read as such).
const ParameterTable<WorkspaceMappingParams>& workspaceMappingParameterTable();
// Empty on success, else one line naming the bad parameter.
std::string validate(const WorkspaceMappingParams& params);

class WorkspaceMapping
{
 public:
  WorkspaceMapping() = default;
  // Throws InputError on bad parameters; normalises the rotation.
  explicit WorkspaceMapping(const WorkspaceMappingParams& params);
  Eigen::Vector3d toWorld(const Eigen::Vector3d& device_position) const;
  Eigen::Vector3d velocityToWorld(const Eigen::Vector3d& device_velocity) const;
  Eigen::Vector3d toDevice(const Eigen::Vector3d& world_position) const;
  Eigen::Vector3d forceToDevice(const Eigen::Vector3d& world_force) const;
  // W: a power at the device (f_device . v_device) as the world's power of the same motion and
  // force (f_world . v_world = scale / force_scale times it; equal for the passive mapping).
  double powerToWorld(double device_power) const;
  // The finger frame's orientation in the device frame -> in the world (unit in, unit out).
  Eigen::Quaterniond orientationToWorld(const Eigen::Quaterniond& device_orientation) const;
  // N m, world -> device frame.
  Eigen::Vector3d torqueToDevice(const Eigen::Vector3d& world_torque) const;
  const WorkspaceMappingParams& params() const
  {
    return params_;
  }

 private:
  WorkspaceMappingParams params_;
  Eigen::Matrix3d rotation_ = Eigen::Matrix3d::Identity();
};
}  // namespace god_finger
