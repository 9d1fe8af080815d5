#include "god_finger/ros/interface_parameters.h"

#include "god_finger/core/input_error.h"
#include "god_finger/ros/parameters.h"

#include <cmath>

namespace god_finger
{
WorldParams readWorldParams(const ros::NodeHandle& pnh)
{
  WorldParams params;
  // The loop's rate sets the time step (the servo loop's range, [10, 10000] Hz).
  const double rate = readDouble(pnh, "rate", 1.0 / params.time_step, 10.0, 1e4, "Hz");
  params.time_step = 1.0 / rate;
  readRows(RosParameterSource(pnh), worldParameterTable(), &params);
  validateOrThrow(params);
  return params;
}

InterfaceConfig readInterfaceConfig(const ParameterSource& source, const std::string& name)
{
  InterfaceConfig config;
  config.name = name;
  config.profile = readDeviceProfile(source);
  WorkspaceMappingParams& mapping = config.mapping;
  mapping.scale = readDouble(source, "workspace_scale", mapping.scale, 0.0, 1e3, "dimensionless", true);
  mapping.force_scale = readDouble(source, "force_scale", mapping.force_scale, 0.0, 1e3, "dimensionless", true);
  mapping.offset = readVector(source, "workspace_offset", Eigen::Vector3d::Zero());
  const Eigen::Vector4d q = readVector(source, "workspace_rotation", Eigen::Vector4d(0, 0, 0, 1));
  mapping.rotation = Eigen::Quaterniond(q[3], q[0], q[1], q[2]);
  const std::string error = validate(mapping);
  if (!error.empty())
  {
    throw InputError("interface '" + name + "': " + error);
  }
  return config;
}
}  // namespace god_finger
