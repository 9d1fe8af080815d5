#include "god_finger/ros/interface_parameters.h"

#include "god_finger/core/input_error.h"
#include "god_finger/ros/parameters.h"

#include <cmath>

namespace god_finger
{
WorldParams readWorldParams(const ros::NodeHandle& pnh)
{
  WorldParams params;
  const double rate = readDouble(pnh, "rate", 1000.0, 10.0, 10000.0, "Hz");
  params.time_step = 1.0 / rate;
  params.solver_iterations = readInt(pnh, "solver_iterations", params.solver_iterations, 1, 1000);
  const std::string model = readString(pnh, "model", contactModelName(params.model));
  if (!parseContactModel(model, &params.model))
  {
    throw InputError("parameter '" + pnh.resolveName("model") + "' = '" + model + "' is not one of " +
                     contactModelNames());
  }
  ContactParams& contact = params.contact;
  // Ranges are the core's (validate() below names the parameter); here only the types.
  contact.max_radius = readDouble(pnh, "r_max", contact.max_radius, -INFINITY, INFINITY, "m");
  contact.distance_constant = readDouble(pnh, "d0", 0.001, -INFINITY, INFINITY, "m");
  contact.alpha = readDouble(pnh, "alpha", contact.alpha, -INFINITY, INFINITY, "dimensionless");
  contact.sub_god_objects = readInt(pnh, "n_sgo", contact.sub_god_objects, -1000000, 1000000);
  contact.max_angle = readDouble(pnh, "tau_a", contact.max_angle, -INFINITY, INFINITY, "rad");
  contact.friction = readDouble(pnh, "friction", contact.friction, -INFINITY, INFINITY, "dimensionless");
  const std::string walk = readString(pnh, "walk", walkVariantName(contact.walk));
  if (!parseWalkVariant(walk, &contact.walk))
  {
    throw InputError("parameter '" + pnh.resolveName("walk") + "' = '" + walk + "' is not one of project, unfold");
  }
  CouplingParams& coupling = params.coupling;
  coupling.proxy_radius = readDouble(pnh, "proxy_radius", coupling.proxy_radius, -INFINITY, INFINITY, "m");
  coupling.proxy_mass = readDouble(pnh, "proxy_mass", coupling.proxy_mass, -INFINITY, INFINITY, "kg");
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
