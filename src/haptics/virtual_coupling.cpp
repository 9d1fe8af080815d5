#include "god_finger/haptics/virtual_coupling.h"

namespace god_finger
{
const ParameterTable<CouplingProfile>& couplingParameterTable()
{
  using P = CouplingProfile;
  static const ParameterTable<P> table = {
      realRow<P>("coupling_stiffness", "N/m", openClosed(0.0, 1e5), "spring between the device and its god-object",
                 [](P& p) -> double& { return p.stiffness; }),
      realRow<P>("coupling_damping", "N s/m", closed(0.0, 1e3), "damper between the device and its god-object",
                 [](P& p) -> double& { return p.damping; }),
      realRow<P>("max_force", "N", openClosed(0.0, 1e4),
                 "the coupling force is saturated here; the device's force limit too",
                 [](P& p) -> double& { return p.max_force; }),
  };
  return table;
}

std::string validate(const CouplingProfile& profile)
{
  return validateRows(couplingParameterTable(), profile);
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
