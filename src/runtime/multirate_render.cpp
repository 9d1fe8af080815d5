#include "god_finger/runtime/multirate_render.h"

#include <algorithm>
#include <limits>

namespace god_finger
{
namespace
{
// Rounds of projection onto the step's planes: one is exact for one plane or orthogonal ones; a
// wedge sharper than a right angle is left at most a few per cent of the crossing inside.
constexpr int kProjectionRounds = 4;

// `v` shortened to length `limit` if longer (direction kept).
Eigen::Vector3d clampedLength(const Eigen::Vector3d& v, double limit)
{
  const double length = v.norm();
  return length > limit ? Eigen::Vector3d(v * (limit / length)) : v;
}

// `point` (m, world) pushed out of every one of the step's planes it is behind (a few rounds of
// projection): the god-object on the planes for a device at `point`.
Eigen::Vector3d outOfPlanes(const MultirateStep& step, const Eigen::Vector3d& point)
{
  Eigen::Vector3d proxy = point;
  for (int round = 0; round < kProjectionRounds; ++round)
  {
    bool pushed = false;
    for (int j = 0; j < step.plane_count; ++j)
    {
      const Eigen::Vector3d& n = step.plane_normals[j];
      const double inside = (proxy - step.proxy_position).dot(n);  // m, < 0: behind the plane
      if (inside < 0.0)
      {
        proxy -= inside * n;
        pushed = true;
      }
    }
    if (!pushed)
    {
      break;
    }
  }
  return proxy;
}

// The prediction's velocity (m/s, world) for the device's `velocity` at `target`: its normal
// part taken out on every plane the prediction is held by.
Eigen::Vector3d predictedVelocity(const MultirateStep& step, const Eigen::Vector3d& target,
                                  const Eigen::Vector3d& velocity)
{
  const Eigen::Vector3d& carried = target;
  Eigen::Vector3d result = velocity;
  for (int j = 0; j < step.plane_count; ++j)
  {
    const Eigen::Vector3d& n = step.plane_normals[j];
    if ((carried - step.proxy_position).dot(n) < 0.0)
    {
      result -= result.dot(n) * n;
    }
  }
  return result;
}
}  // namespace

Eigen::Vector3d predictedProxy(const MultirateStep& step, const Eigen::Vector3d& target)
{
  return outOfPlanes(step, target);
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
  if (to_predicted.norm() <= delta + moved)
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
  const CouplingForce spring = couplingForce(coupling, device.target, device.velocity, anchor,
                                             predictedVelocity(step, device.target, device.velocity));
  const double stored = 0.5 * state->force.squaredNorm() / coupling.stiffness;  // J, in the coupling's spring
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
