#include "god_finger/physics/world_params.h"

#include "god_finger/core/input_error.h"

#include <sstream>

namespace god_finger
{
std::string validate(const WorldParams& params)
{
  // Written as !(in range) so that NaN is out of range.
  if (!(params.time_step >= 1e-5 && params.time_step <= 0.1))
  {
    return outOfRange("time_step", params.time_step, "[1e-05, 0.1]", "s");
  }
  if (!(params.solver_iterations >= 1 && params.solver_iterations <= 1000))
  {
    return outOfRange("solver_iterations", params.solver_iterations, "[1, 1000]", "count");
  }
  if (!params.gravity.allFinite())
  {
    return "parameter 'gravity' must be finite (m/s^2)";
  }
  const CouplingParams& c = params.coupling;
  const std::string coupling_error = validate(static_cast<const CouplingProfile&>(c));
  if (!coupling_error.empty())
  {
    return coupling_error;
  }
  if (!(c.proxy_mass > 0.0 && c.proxy_mass <= 10.0))
  {
    return outOfRange("proxy_mass", c.proxy_mass, "(0, 10]", "kg");
  }
  if (!(c.proxy_radius > 0.0 && c.proxy_radius <= 0.1))
  {
    return outOfRange("proxy_radius", c.proxy_radius, "(0, 0.1]", "m");
  }
  const std::string stability_error = couplingStabilityError(c, c.proxy_mass, params.time_step);
  if (!stability_error.empty())
  {
    return stability_error;
  }
  if (!(params.soft_finger.spinning_friction >= 0.0 && params.soft_finger.spinning_friction <= 1.0))
  {
    return outOfRange("spinning_friction", params.soft_finger.spinning_friction, "[0, 1]", "m");
  }
  if (!(params.soft_finger.rolling_friction > 0.0 && params.soft_finger.rolling_friction <= 1.0))
  {
    return outOfRange("rolling_friction", params.soft_finger.rolling_friction, "(0, 1]", "m");
  }
  if (!(params.pad.stiffness > 0.0 && params.pad.stiffness <= 1e7))
  {
    return outOfRange("pad_stiffness", params.pad.stiffness, "(0, 1e+07]", "N/m");
  }
  if (!(params.pad.damping >= 0.0 && params.pad.damping <= 1e5))
  {
    return outOfRange("pad_damping", params.pad.damping, "[0, 1e+05]", "N s/m");
  }
  if (!(params.walk_edge_per_max_radius > 0.0 && params.walk_edge_per_max_radius <= 10.0))
  {
    return outOfRange("walk_edge_per_max_radius", params.walk_edge_per_max_radius, "(0, 10]", "dimensionless");
  }
  return validate(params.contact);
}

void validateOrThrow(const WorldParams& params)
{
  const std::string error = validate(params);
  if (!error.empty())
  {
    throw InputError(error);
  }
}

std::string couplingStabilityError(const CouplingProfile& c, double proxy_mass, double time_step)
{
  // The coupling force is explicit (from the proxy's state at the start of the step, then
  // symplectic Euler): in free space it is stable iff k dt^2 / m + 2 c dt / m < 4.
  const double stability = (c.stiffness * time_step + 2.0 * c.damping) * time_step / proxy_mass;
  if (stability < 4.0)
  {
    return "";
  }
  std::ostringstream message;
  message << "coupling unstable at this time step: (coupling_stiffness * dt + 2 coupling_damping) * dt / proxy_mass = "
          << stability << " must be < 4 (stiffness " << c.stiffness << " N/m, damping " << c.damping
          << " N s/m, proxy_mass " << proxy_mass << " kg, dt " << time_step
          << " s): lower the stiffness, damping or time step, or raise proxy_mass";
  return message.str();
}
}  // namespace god_finger
