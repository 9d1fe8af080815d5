// The safety between force commands and a haptic device's motors, device-independent. Every
// force a device applies is this guard's output(); the rules, in the order they apply:
//  1. command(): a command with a NaN or Inf component is rejected (counted) and the last good
//     one stays; a finite one is saturated to max_force (direction kept): the guard's input,
//     commanded().
//  2. Watchdog: when no command has arrived for `command_timeout`, the target ramps linearly to
//     zero within `ramp_time` and stays there until a new command arrives.
//  3. Soft start: the target is scaled by s = min(1, (t - t0) / soft_start), t0 the start: the
//     first command, the first command after the watchdog tripped, or resume(). So the hand
//     never gets a step of force when the device starts or resumes (soft_start = 0: no ramp).
//  4. Continuous limit (a thermal-like budget): E, the exponential average of |F|^2 of the
//     output with time constant `thermal_time_constant` (tau), dE/dt = (|F|^2 - E) / tau, must
//     stay under Fc^2, Fc = min(continuous_force, max_force). Each period dt the target's
//     magnitude is capped to what keeps E(t + dt) <= Fc^2:
//       |F|^2 <= (Fc^2 - e E) / (1 - e),  e = exp(-dt / tau).
//     A cold device may exceed Fc up to max_force for a while (from E = 0, a held F for
//     tau ln(F^2 / (F^2 - Fc^2))); a held force then settles at Fc; the budget refills with
//     time constant tau when the force drops. continuous_force >= max_force: no limit.
//  5. Rate limit: the output moves toward the target by at most max_force_rate * dt per call
//     (|dF/dt| <= max_force_rate, also on the watchdog's ramp and on the budget's fall, which
//     may then exceed Fc^2 by what the rate limit takes to get there).
//  6. stop(): the output is zero at once (not rate-limited) and stays zero until resume(),
//     which restarts the soft start. Commands are still taken (and the watchdog runs) while
//     stopped.
// An oriented finger's torque goes through rules 2, 3 and 6 of the same guard (scale(): the
// watchdog's ramp times the soft start, zero while stopped or before the first force command):
// it starts, resumes and fades with the force, on the force's clock, with no ramp of its own.
// Its saturation is the profile's max_torque (haptics/device_profile.h renderableTorque); rules 4
// and 5 are the force's only.
// Units: N, N/s and s, the device frame. Time is passed in (any monotonic clock), so the guard is
// testable. Invariants: |output| <= max_force, |output(t2) - output(t1)| <= max_force_rate
// (t2 - t1) except at stop(). output() advances the state: call it with non-decreasing times (a
// call at the same or an earlier time returns the last output unchanged). All calls are
// real-time safe (no allocation, no lock, no log); the constructor is not.
#pragma once

#include "god_finger/support/parameter_table.h"

#include <Eigen/Core>
#include <string>

namespace god_finger
{
struct ForceGuardParams
{
  double command_timeout = 0.02;        // s: watchdog
  double ramp_time = 0.01;              // s: from the last force to zero
  double soft_start = 0.5;              // s: from zero to the command at start and resume; 0: none
  double max_force_rate = 1e4;          // N/s: |dF/dt| of the output
  double continuous_force = 1e4;        // N: the budget's sustained force; >= max_force: no limit
  double thermal_time_constant = 10.0;  // s: the budget's averaging time constant
};
// command_timeout, ramp_time, soft_start, max_force_rate, continuous_force,
// thermal_time_constant. The limit, max_force, is not here: it is the device's one limit, the
// coupling's max_force row (CouplingProfile, DeviceProfile::coupling), given to the guard.
const ParameterTable<ForceGuardParams>& forceGuardParameterTable();
// Empty on success, else "parameter 'NAME' = VALUE is out of range [..] (unit)".
std::string validate(const ForceGuardParams& params);

// The soft start's scale (rule 3): s = min(1, since / soft_start) in [0, 1], `since` (s) the
// time since the start; soft_start = 0: 1 (no ramp). The servo loop ramps a re-acquired
// finger's target with it too. Real-time safe.
double softStartScale(double since, double soft_start);

class ForceGuard
{
 public:
  // max_force (N): the device's limit (its profile's coupling.max_force). Throws InputError on
  // bad parameters (max_force checked by the coupling's max_force row).
  ForceGuard(double max_force, const ForceGuardParams& params);
  // A new command at `time`. Returns false (and counts it) if it is not finite.
  bool command(double time, const Eigen::Vector3d& force);
  // The force to apply at `time` (non-decreasing; see above). Advances the soft start, the
  // budget and the rate limit.
  Eigen::Vector3d output(double time);
  // What rules 2, 3 and 6 multiply the command by at `time`, in [0, 1]: the watchdog's ramp
  // times the soft start (softStartScale), 0 while stopped or before the first command. The
  // servo loop scales an oriented finger's torque by it. Reads the state, advances nothing;
  // real-time safe.
  double scale(double time) const;
  // The last good command, saturated (N, device frame): the guard's input.
  const Eigen::Vector3d& commanded() const
  {
    return last_force_;
  }
  // All force off at once (output zero until resume()).
  void stop();
  // Force back, ramped in over soft_start from `time`. No effect unless stopped.
  void resume(double time);
  bool stopped() const
  {
    return stopped_;
  }
  long rejected() const
  {
    return rejected_;
  }
  long saturated() const
  {
    return saturated_;
  }
  // Outputs the continuous budget capped.
  long budgetLimited() const
  {
    return budget_limited_;
  }
  // The budget's state E (N^2): the exponential average of |output|^2.
  double thermalLoad() const
  {
    return load_;
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
  double maxForce() const
  {
    return max_force_;
  }

 private:
  double max_force_;  // N
  ForceGuardParams params_;
  Eigen::Vector3d last_force_ = Eigen::Vector3d::Zero();  // saturated
  double last_command_time_ = 0.0;
  bool have_command_ = false;
  double start_time_ = 0.0;  // s: t0 of the soft start
  bool stopped_ = false;
  Eigen::Vector3d output_ = Eigen::Vector3d::Zero();  // the last output
  double output_time_ = 0.0;
  bool have_output_ = false;  // output_time_ is set
  double load_ = 0.0;         // N^2: E
  long rejected_ = 0;
  long saturated_ = 0;
  long budget_limited_ = 0;
};
}  // namespace god_finger
