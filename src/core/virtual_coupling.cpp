#include "god_finger/core/virtual_coupling.h"

#include <sstream>

namespace god_finger
{
std::string validate(const CouplingProfile& profile)
{
  std::ostringstream message;
  if (!(profile.stiffness > 0.0 && profile.stiffness <= 1e5))
  {
    message << "parameter 'coupling_stiffness' = " << profile.stiffness << " is out of range (0, 1e+05] (N/m)";
  }
  else if (!(profile.damping >= 0.0 && profile.damping <= 1e3))
  {
    message << "parameter 'coupling_damping' = " << profile.damping << " is out of range [0, 1000] (N s/m)";
  }
  else if (!(profile.max_force > 0.0 && profile.max_force <= 1e4))
  {
    message << "parameter 'max_force' = " << profile.max_force << " is out of range (0, 1e+04] (N)";
  }
  return message.str();
}

CouplingForce couplingForce(const CouplingProfile& profile, const Eigen::Vector3d& interface_position,
                            const Eigen::Vector3d& interface_velocity, const Eigen::Vector3d& proxy_position,
                            const Eigen::Vector3d& proxy_velocity)
{
  CouplingForce result;
  result.on_proxy = profile.stiffness * (interface_position - proxy_position) +
                    profile.damping * (interface_velocity - proxy_velocity);
  const double magnitude = result.on_proxy.norm();
  result.saturated = magnitude > profile.max_force;
  if (result.saturated)
  {
    result.on_proxy *= profile.max_force / magnitude;
  }
  return result;
}
}  // namespace god_finger
