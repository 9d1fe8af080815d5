#include "god_finger/core/force_guard.h"

#include "god_finger/core/input_error.h"
#include "god_finger/core/virtual_coupling.h"

#include <cmath>
#include <sstream>

namespace god_finger
{
const ParameterTable<ForceGuardParams>& forceGuardParameterTable()
{
  using P = ForceGuardParams;
  static const ParameterTable<P> table = {
      realRow<P>("command_timeout", "s", openClosed(0.0, 10.0),
                 "watchdog: no force command for this long ramps the force down",
                 [](P& p) -> double& { return p.command_timeout; }),
      realRow<P>("ramp_time", "s", openClosed(0.0, 1.0), "from the last commanded force to zero",
                 [](P& p) -> double& { return p.ramp_time; }),
  };
  return table;
}

std::string validate(const ForceGuardParams& params)
{
  const CouplingProfile limit{1.0, 0.0, params.max_force};
  const std::string error = validateRows(couplingParameterTable(), limit);
  return error.empty() ? validateRows(forceGuardParameterTable(), params) : error;
}

ForceGuard::ForceGuard(const ForceGuardParams& params) : params_(params)
{
  const std::string error = validate(params);
  if (!error.empty())
  {
    throw InputError(error);
  }
}

bool ForceGuard::command(double time, const Eigen::Vector3d& force)
{
  if (!force.allFinite() || !std::isfinite(time))
  {
    ++rejected_;
    return false;
  }
  const double magnitude = force.norm();
  last_force_ = force;
  if (magnitude > params_.max_force)
  {
    last_force_ *= params_.max_force / magnitude;
    ++saturated_;
  }
  last_command_time_ = time;
  have_command_ = true;
  return true;
}

Eigen::Vector3d ForceGuard::output(double time)
{
  if (!have_command_)
  {
    return Eigen::Vector3d::Zero();
  }
  const double late = time - last_command_time_ - params_.command_timeout;
  if (late <= 0.0)
  {
    return last_force_;
  }
  const double remaining = 1.0 - late / params_.ramp_time;
  return remaining > 0.0 ? Eigen::Vector3d(remaining * last_force_) : Eigen::Vector3d::Zero();
}
}  // namespace god_finger
