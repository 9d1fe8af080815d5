#include "god_finger/haptics/force_guard.h"

#include "god_finger/support/input_error.h"
#include "god_finger/haptics/virtual_coupling.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace god_finger
{
double softStartScale(double since, double soft_start)
{
  return soft_start > 0.0 ? std::clamp(since / soft_start, 0.0, 1.0) : 1.0;
}

const ParameterTable<ForceGuardParams>& forceGuardParameterTable()
{
  using P = ForceGuardParams;
  static const ParameterTable<P> table = {
      realRow<P>("command_timeout", "s", openClosed(0.0, 10.0),
                 "watchdog: no force command for this long ramps the force down",
                 [](P& p) -> double& { return p.command_timeout; }),
      realRow<P>("ramp_time", "s", openClosed(0.0, 1.0), "from the last commanded force to zero",
                 [](P& p) -> double& { return p.ramp_time; }),
      realRow<P>("soft_start", "s", closed(0.0, 10.0),
                 "force ramps in from zero over this at start, after the watchdog and on resume (0: at once)",
                 [](P& p) -> double& { return p.soft_start; }),
      realRow<P>("max_force_rate", "N/s", openClosed(0.0, 1e6),
                 "limit on the rate of change of the force (norm of dF/dt)",
                 [](P& p) -> double& { return p.max_force_rate; }),
      realRow<P>("continuous_force", "N", openClosed(0.0, 1e4),
                 "sustained force: the average of the squared force over thermal_time_constant stays under its square "
                 "(>= max_force: no limit)",
                 [](P& p) -> double& { return p.continuous_force; }),
      realRow<P>("thermal_time_constant", "s", openClosed(0.0, 1000.0),
                 "time constant of the continuous-force budget's average",
                 [](P& p) -> double& { return p.thermal_time_constant; }),
  };
  return table;
}

std::string validate(const ForceGuardParams& params)
{
  return validateRows(forceGuardParameterTable(), params);
}

ForceGuard::ForceGuard(double max_force, const ForceGuardParams& params) : max_force_(max_force), params_(params)
{
  CouplingProfile limit;  // only its max_force row matters; the others keep their valid defaults
  limit.max_force = max_force;
  std::string error = validate(limit);
  if (error.empty())
  {
    error = validate(params);
  }
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
  if (!have_command_ || timedOut(time))
  {
    start_time_ = time;  // start, or resume after the watchdog: soft start
  }
  const double magnitude = force.norm();
  last_force_ = force;
  if (magnitude > max_force_)
  {
    last_force_ *= max_force_ / magnitude;
    ++saturated_;
  }
  last_command_time_ = time;
  have_command_ = true;
  return true;
}

void ForceGuard::stop()
{
  stopped_ = true;
  output_.setZero();
}

void ForceGuard::resume(double time)
{
  if (stopped_)
  {
    stopped_ = false;
    start_time_ = time;
  }
}

double ForceGuard::scale(double time) const
{
  if (!have_command_ || stopped_)
  {
    return 0.0;
  }
  // 2. Watchdog.
  const double late = time - last_command_time_ - params_.command_timeout;
  const double watchdog = late <= 0.0 ? 1.0 : std::max(0.0, 1.0 - late / params_.ramp_time);
  // 3. Soft start.
  const double soft = softStartScale(time - start_time_, params_.soft_start);
  return watchdog * soft;
}

Eigen::Vector3d ForceGuard::output(double time)
{
  if (!std::isfinite(time) || (have_output_ && time <= output_time_))
  {
    return output_;
  }
  const double dt = have_output_ ? time - output_time_ : 0.0;
  output_time_ = time;
  have_output_ = true;
  // 2., 3. and 6.
  Eigen::Vector3d target = scale(time) * last_force_;
  // 4. Continuous budget.
  const double decay = std::exp(-dt / params_.thermal_time_constant);
  const double continuous = std::min(params_.continuous_force, max_force_);
  if (continuous < max_force_ && decay < 1.0)
  {
    const double cap2 = (continuous * continuous - decay * load_) / (1.0 - decay);
    const double cap = cap2 > 0.0 ? std::sqrt(cap2) : 0.0;
    const double magnitude = target.norm();
    if (magnitude > cap)
    {
      target *= cap / magnitude;
      ++budget_limited_;
    }
  }
  // 5. Rate limit (the first output has no elapsed time: it stays at zero).
  const Eigen::Vector3d change = target - output_;
  const double step = params_.max_force_rate * dt;
  const double change_norm = change.norm();
  output_ += change_norm > step ? Eigen::Vector3d(change * (step / change_norm)) : change;
  load_ = decay * load_ + (1.0 - decay) * output_.squaredNorm();
  return output_;
}
}  // namespace god_finger
