#include "god_finger/core/force_guard.h"

#include "god_finger/core/input_error.h"

#include <cmath>
#include <sstream>

namespace god_finger
{
std::string validate(const ForceGuardParams& params)
{
  if (!(params.max_force > 0.0 && params.max_force <= 1e3))
  {
    return outOfRange("max_force", params.max_force, "(0, 1000]", "N");
  }
  if (!(params.command_timeout > 0.0 && params.command_timeout <= 10.0))
  {
    return outOfRange("command_timeout", params.command_timeout, "(0, 10]", "s");
  }
  if (!(params.ramp_time > 0.0 && params.ramp_time <= 1.0))
  {
    return outOfRange("ramp_time", params.ramp_time, "(0, 1]", "s");
  }
  return "";
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
