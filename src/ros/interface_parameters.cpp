#include "interface_parameters.h"

#include "god_finger/support/input_error.h"
#include "node_parameters.h"
#include "parameters.h"

#include <cmath>

namespace god_finger
{
WorldParams readWorldParams(const ros::NodeHandle& pnh)
{
  WorldParams params;
  // The loop's rate (servoLoopParameterTable()) sets the time step.
  params.time_step = 1.0 / readLoopParams(pnh).rate;
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
  readRows(source, workspaceMappingParameterTable(), &mapping);
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
