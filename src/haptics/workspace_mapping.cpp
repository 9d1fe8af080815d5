#include "god_finger/haptics/workspace_mapping.h"

#include "god_finger/support/input_error.h"

#include <cmath>
#include <sstream>

namespace god_finger
{
const ParameterTable<WorkspaceMappingParams>& workspaceMappingParameterTable()
{
  using P = WorkspaceMappingParams;
  static const ParameterTable<P> table = {
      realRow<P>("workspace_scale", "dimensionless", openClosed(0.0, 1e3), "world metres per device metre",
                 [](P& p) -> double& { return p.scale; }),
      realRow<P>("force_scale", "dimensionless", openClosed(0.0, 1e3), "device newtons per world newton",
                 [](P& p) -> double& { return p.force_scale; }),
  };
  return table;
}

std::string validate(const WorkspaceMappingParams& params)
{
  std::ostringstream message;
  const std::string row_error = validateRows(workspaceMappingParameterTable(), params);
  if (!row_error.empty())
  {
    return row_error;
  }
  if (!params.offset.allFinite())
  {
    message << "parameter 'workspace_offset' must be finite (m)";
  }
  else if (!params.rotation.coeffs().allFinite() || std::abs(params.rotation.norm() - 1.0) > 1e-3)
  {
    message << "parameter 'workspace_rotation' must be a unit quaternion (norm " << params.rotation.norm() << ")";
  }
  return message.str();
}

WorkspaceMapping::WorkspaceMapping(const WorkspaceMappingParams& params) : params_(params)
{
  const std::string error = validate(params);
  if (!error.empty())
  {
    throw InputError(error);
  }
  params_.rotation.normalize();
  rotation_ = params_.rotation.toRotationMatrix();
}

Eigen::Vector3d WorkspaceMapping::toWorld(const Eigen::Vector3d& device_position) const
{
  return params_.offset + params_.scale * (rotation_ * device_position);
}

Eigen::Vector3d WorkspaceMapping::velocityToWorld(const Eigen::Vector3d& device_velocity) const
{
  return params_.scale * (rotation_ * device_velocity);
}

Eigen::Vector3d WorkspaceMapping::toDevice(const Eigen::Vector3d& world_position) const
{
  return rotation_.transpose() * (world_position - params_.offset) / params_.scale;
}

Eigen::Vector3d WorkspaceMapping::forceToDevice(const Eigen::Vector3d& world_force) const
{
  return params_.force_scale * (rotation_.transpose() * world_force);
}

double WorkspaceMapping::powerToWorld(double device_power) const
{
  return device_power * params_.scale / params_.force_scale;
}

Eigen::Quaterniond WorkspaceMapping::orientationToWorld(const Eigen::Quaterniond& device_orientation) const
{
  return params_.rotation * device_orientation;
}

Eigen::Vector3d WorkspaceMapping::torqueToDevice(const Eigen::Vector3d& world_torque) const
{
  return rotation_.transpose() * world_torque;
}
}  // namespace god_finger
