// The safety between force commands and a haptic device's motors, device-independent:
//  - a command with a NaN or Inf component is rejected (counted) and the last good one stays;
//  - the force is saturated to the device profile's maximum (direction kept);
//  - when no command has arrived for `command_timeout`, the output ramps linearly to zero
//    within `ramp_time`, and stays there until a new command arrives (then it applies at once).
// Units: N and s. Time is passed in (any monotonic clock), so the guard is testable and
// allocation-free. Invariant: |output| <= max_force at every time.
#pragma once

#include "god_finger/core/parameter_table.h"

#include <Eigen/Core>
#include <string>

namespace god_finger
{
struct ForceGuardParams
{
  double max_force = 8.0;         // N: set to the device profile's limit (coupling max_force)
  double command_timeout = 0.02;  // s: watchdog
  double ramp_time = 0.01;        // s: from the last force to zero
};
// command_timeout, ramp_time (the limit is the coupling's max_force row).
const ParameterTable<ForceGuardParams>& forceGuardParameterTable();
// Empty on success, else "parameter 'NAME' = VALUE is out of range [..] (unit)".
std::string validate(const ForceGuardParams& params);

class ForceGuard
{
 public:
  // Throws InputError on bad parameters.
  explicit ForceGuard(const ForceGuardParams& params);
  // A new command at `time`. Returns false (and counts it) if it is not finite.
  bool command(double time, const Eigen::Vector3d& force);
  // The force to apply at `time` (>= the last command's time).
  Eigen::Vector3d output(double time);
  long rejected() const
  {
    return rejected_;
  }
  long saturated() const
  {
    return saturated_;
  }
  // True while the watchdog holds the output below the last command.
  bool timedOut(double time) const
  {
    return have_command_ && time - last_command_time_ > params_.command_timeout;
  }
  const ForceGuardParams& params() const
  {
    return params_;
  }

 private:
  ForceGuardParams params_;
  Eigen::Vector3d last_force_ = Eigen::Vector3d::Zero();  // saturated
  double last_command_time_ = 0.0;
  bool have_command_ = false;
  long rejected_ = 0;
  long saturated_ = 0;
};
}  // namespace god_finger
