#include "god_finger/haptics/passivity_controller.h"

#include "god_finger/support/input_error.h"

#include <algorithm>
#include <cmath>

namespace god_finger
{
namespace
{
// Below this |v|^2 dt (m^2/s) the device is still: no damping can take energy out of it.
constexpr double kStill = 1e-12;
}  // namespace

const ParameterTable<PassivityParams>& passivityParameterTable()
{
  using P = PassivityParams;
  static const ParameterTable<P> table = {
      realRow<P>("passivity_damping_limit", "N s/m", closed(0.0, 1000.0),
                 "the most damping the passivity controller adds at the device to keep the loop behind it passive "
                 "(0: controller off, and the physics port's too)",
                 [](P& p) -> double& { return p.passivity_damping_limit; }),
      realRow<P>("passivity_min_damping", "N s/m", closed(0.0, 100.0),
                 "while the force is on, the loop behind the device must dissipate at least as this damper would",
                 [](P& p) -> double& { return p.passivity_min_damping; }),
      realRow<P>("passivity_reservoir", "J", closed(0.0, 10.0),
                 "the most energy the passivity observer banks for the loop to give back later",
                 [](P& p) -> double& { return p.passivity_reservoir; }),
      realRow<P>("passivity_drift_return", "1/s", closed(0.0, 100.0),
                 "how fast the physics port's passivity controller (the physics node's, across the topic "
                 "topologies; the delay sweep's two-port form) returns the hand's position it held out of a contact, "
                 "as far as the energy the device put in allows",
                 [](P& p) -> double& { return p.passivity_drift_return; }),
      realRow<P>("passivity_contact_credit", "J", closed(0.0, 1.0),
                 "what the physics port's passivity controller may let out before the device has put it in, so that "
                 "a contact can start (in free motion the device renders no force and puts nothing in); that port's "
                 "energy margin never goes below minus this",
                 [](P& p) -> double& { return p.passivity_contact_credit; }),
  };
  return table;
}

std::string validate(const PassivityParams& params)
{
  return validateRows(passivityParameterTable(), params);
}

PassivityController::PassivityController(const PassivityParams& params, double period)
    : params_(params), period_(period)
{
  const std::string error = validate(params);
  if (!error.empty())
  {
    throw InputError(error);
  }
  if (!(period > 0.0 && period <= 1.0))
  {
    throw InputError("passivity controller: period " + std::to_string(period) + " s is not in (0, 1]");
  }
}

Eigen::Vector3d PassivityController::apply(const Eigen::Vector3d& force, const Eigen::Vector3d& velocity,
                                           double max_force)
{
  damping_ = 0.0;
  cut_ = 0.0;
  if (!force.allFinite() || !velocity.allFinite())
  {
    return force;
  }
  const double speed2_dt = velocity.squaredNorm() * period_;
  const double asked = force.isZero(0.0) ? 0.0 : params_.passivity_min_damping * speed2_dt;
  Eigen::Vector3d rendered = force;
  const double unmodified = bank_ - force.dot(velocity) * period_ - asked;
  if (params_.passivity_damping_limit > 0.0)
  {
    if (unmodified < 0.0 && speed2_dt > kStill)
    {
      damping_ = std::min(params_.passivity_damping_limit, -unmodified / speed2_dt);
      rendered -= damping_ * velocity;
    }
    // The observer's energy about to go below zero (the damper capped, the loop giving the hand
    // more than it ever put in): that much of the force's push along the motion is taken away,
    // never more than the push itself (E >= 0 before this tick). A debt of the bank alone is
    // left to the damper, which pays it over the next ticks.
    const double made_up = rendered.dot(velocity) * period_ - energy_;  // J
    if (made_up > 0.0)
    {
      const double speed = velocity.norm();
      cut_ = std::min(rendered.dot(velocity) / speed, made_up / (speed * period_));
      rendered -= (cut_ / speed) * velocity;
    }
    if (damping_ > 0.0 || cut_ > 0.0)
    {
      ++active_ticks_;
    }
  }
  const double length = rendered.norm();
  if (length > max_force)
  {
    rendered *= max_force / length;
  }
  const double taken = (force - rendered).dot(velocity) * period_;  // J: what the controller took out
  dissipated_ += std::max(0.0, taken);
  const double tick = -rendered.dot(velocity) * period_;
  bank_ = std::min(params_.passivity_reservoir, bank_ + tick - asked);
  energy_ += tick;
  lowest_energy_ = std::min(lowest_energy_, energy_);
  return rendered;
}

void PassivityController::reset(double stored)
{
  reset();
  if (stored > 0.0 && std::isfinite(stored))
  {
    energy_ = stored;
    lowest_energy_ = stored;
    bank_ = std::min(params_.passivity_reservoir, stored);
  }
}

void PassivityController::reset()
{
  bank_ = 0.0;
  cut_ = 0.0;
  energy_ = 0.0;
  lowest_energy_ = 0.0;
  damping_ = 0.0;
  dissipated_ = 0.0;
  active_ticks_ = 0;
}
}  // namespace god_finger
