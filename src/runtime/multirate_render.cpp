#include "god_finger/runtime/multirate_render.h"

#include <algorithm>
#include <limits>

namespace god_finger
{
namespace
{
// `v` shortened to length `limit` if longer (direction kept).
Eigen::Vector3d clampedLength(const Eigen::Vector3d& v, double limit)
{
  const double length = v.norm();
  return length > limit ? Eigen::Vector3d(v * (limit / length)) : v;
}
}  // namespace

bool renderMultirate(const CouplingProfile& coupling, int recovery_periods, const MultirateDevice& device,
                     const MultirateStep& step, MultirateState* state)
{
  if (state->exact && step.lag == 0)
  {
    state->force = step.user_force;
    state->anchor = step.proxy_position;
    return true;
  }
  const double delta = coupling.max_force / (coupling.stiffness * recovery_periods);
  const double bound = coupling.stiffness * ((device.target - device.previous_target).norm() + delta) +
                       coupling.damping * (device.velocity - device.previous_velocity).norm();
  const Eigen::Vector3d to_proxy = step.proxy_position - state->anchor;
  if (to_proxy.norm() <= delta)
  {
    state->anchor = step.proxy_position;
  }
  else
  {
    state->anchor += clampedLength(to_proxy, delta);
  }
  if (step.lag == 0 && state->anchor == step.proxy_position && (step.user_force - state->force).norm() <= bound)
  {
    state->force = step.user_force;
    state->exact = true;
    return true;
  }
  // A spring to the anchor (yielding as a soft body does), damping on the device's own velocity
  // only, saturated.
  Eigen::Vector3d anchor = state->anchor;
  if (step.contact_stiffness < std::numeric_limits<double>::infinity())
  {
    const Eigen::Vector3d& n = step.contact_normal;
    const double k_c = coupling.stiffness;
    const double k_s = step.contact_stiffness;
    const double pressed = step.user_force.dot(n);                  // N: the step's force along n
    const double past = (device.target - step.step_target).dot(n);  // m: the device's move out of the body
    const double along = std::max(0.0, pressed - k_c * k_s / (k_c + k_s) * past);
    // Where the proxy would be along n for that force: the device's place plus along / k_c.
    anchor += n * (device.target.dot(n) + along / k_c - state->anchor.dot(n));
  }
  const CouplingForce spring = couplingForce(coupling, device.target, device.velocity, anchor, Eigen::Vector3d::Zero());
  state->force = state->force + clampedLength(-spring.on_proxy - state->force, bound);
  state->exact = false;
  return false;
}
}  // namespace god_finger
