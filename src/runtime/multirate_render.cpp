#include "god_finger/runtime/multirate_render.h"

#include "god_finger/physics/world_state.h"

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

// Whether the device at `target` presses into one of the step's contact planes (behind it).
bool pressesIntoAPlane(const MultirateStep& step, const Eigen::Vector3d& target)
{
  for (int j = 0; j < step.plane_count; ++j)
  {
    if ((target - step.proxy_position).dot(step.plane_normals[j]) < 0.0)
    {
      return true;
    }
  }
  return false;
}
}  // namespace

Eigen::Vector3d predictedProxy(const MultirateStep& step, const Eigen::Vector3d& target)
{
  return pressesIntoAPlane(step, target) ? step.proxy_position : target;
}

MultirateStep multirateStepOf(const InterfaceState& state, long lag)
{
  MultirateStep step;
  step.proxy_position = state.proxy_position;
  step.user_force = state.user_force;
  step.lag = lag;
  step.step_target = state.interface_position;
  step.contact_stiffness = state.contact_stiffness;
  step.contact_normal = state.contact_normal;
  step.plane_count = std::min(state.contact_count, MultirateStep::kMaxPlanes);
  for (int c = 0; c < step.plane_count; ++c)
  {
    step.plane_normals[c] = state.contacts[c].normal;
  }
  return step;
}

Eigen::Vector3d heldForce(const CouplingProfile& coupling, const MultirateStep& step, const Eigen::Vector3d& target,
                          const Eigen::Vector3d& velocity)
{
  if (!pressesIntoAPlane(step, target))
  {
    return Eigen::Vector3d::Zero();
  }
  return -couplingForce(coupling, target, velocity, step.proxy_position, Eigen::Vector3d::Zero()).on_proxy;
}

bool renderMultirate(const CouplingProfile& coupling, int recovery_periods, const MultirateDevice& device,
                     const MultirateStep& step, MultirateState* state, PassivityController* hold)
{
  if (state->exact && step.lag == 0)
  {
    state->force = step.user_force;
    state->anchor = step.proxy_position;
    return true;
  }
  const bool hold_begins = state->exact;
  const double moved = (device.target - device.previous_target).norm();  // m, this tick
  const double delta = coupling.max_force / (coupling.stiffness * recovery_periods);
  const double bound =
      coupling.stiffness * (moved + delta) + coupling.damping * (device.velocity - device.previous_velocity).norm();
  // On time (lag 0) the step is this tick's: its proxy is the prediction.
  const Eigen::Vector3d predicted = step.lag == 0 ? step.proxy_position : predictedProxy(step, device.target);
  const Eigen::Vector3d to_predicted = predicted - state->anchor;
  // Out of every plane the prediction is the hand itself: the anchor is there at once (a held
  // friction stretch let go moves no anchor across the hand's way; the force's bound spreads it).
  const bool pressing = pressesIntoAPlane(step, device.target);
  const bool free = step.lag != 0 && !pressing;
  if (free || to_predicted.norm() <= delta + moved)
  {
    state->anchor = predicted;
  }
  else
  {
    state->anchor += clampedLength(to_predicted, delta + moved);
  }
  if (step.lag == 0 && state->anchor == step.proxy_position && (step.user_force - state->force).norm() <= bound)
  {
    state->force = step.user_force;
    state->exact = true;
    return true;
  }
  // A spring to the anchor (yielding as a soft body does), damping on the device's velocity
  // relative to the prediction's, saturated.
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
  const Eigen::Vector3d anchor_velocity = pressing ? Eigen::Vector3d(Eigen::Vector3d::Zero()) : device.velocity;
  const CouplingForce spring = couplingForce(coupling, device.target, device.velocity, anchor, anchor_velocity);
  // J: what the coupling's spring holds, and a soft body's in series with it.
  const double compliance =
      1.0 / coupling.stiffness +
      (step.contact_stiffness < std::numeric_limits<double>::infinity() ? 1.0 / step.contact_stiffness : 0.0);
  const double stored = 0.5 * state->force.squaredNorm() * compliance;
  state->force = state->force + clampedLength(-spring.on_proxy - state->force, bound);
  state->exact = false;
  if (hold != nullptr)
  {
    if (hold_begins)
    {
      hold->reset(stored);
    }
    state->force = hold->apply(state->force, device.velocity, coupling.max_force);
  }
  return false;
}
}  // namespace god_finger
