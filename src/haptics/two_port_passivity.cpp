#include "god_finger/haptics/two_port_passivity.h"

#include "god_finger/support/input_error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace god_finger
{
namespace
{
// Below this |v|^2 dt (m^2/s) the handle is still: no damping can take energy out of it.
constexpr double kStill = 1e-12;

void checkPort(const PassivityParams& params, double period, const char* side)
{
  const std::string error = validate(params);
  if (!error.empty())
  {
    throw InputError(error);
  }
  if (!(period > 0.0 && period <= 1.0))
  {
    throw InputError(std::string(side) + " passivity: period " + std::to_string(period) + " s is not in (0, 1]");
  }
}
}  // namespace

void PortEnergyObserver::observe(double power, double dt)
{
  if (!std::isfinite(power) || !std::isfinite(dt))
  {
    return;
  }
  if (power > 0.0)
  {
    in_ += power * dt;
  }
  else
  {
    out_ -= power * dt;
  }
}

void RemoteEnergy::receive(const EnergyPacket& packet)
{
  if (!std::isfinite(packet.energy_in) || !std::isfinite(packet.stamp))
  {
    return;
  }
  if (packet.energy_in > energy_in_)
  {
    energy_in_ = packet.energy_in;
  }
  stamp_ = std::max(stamp_, packet.stamp);
}

DevicePortPassivity::DevicePortPassivity(const PassivityParams& params, double period)
    : params_(params), period_(period)
{
  checkPort(params, period, "device port");
}

Eigen::Vector3d DevicePortPassivity::apply(const Eigen::Vector3d& force, const Eigen::Vector3d& velocity,
                                           double max_force)
{
  damping_ = 0.0;
  if (!force.allFinite() || !velocity.allFinite())
  {
    return force;
  }
  Eigen::Vector3d rendered = force;
  const double speed2_dt = velocity.squaredNorm() * period_;
  if (params_.passivity_damping_limit > 0.0 && speed2_dt > kStill)
  {
    // The energy this tick would let out to the hand, and how far that takes E_out past the
    // physics' E_in: only that much is taken, never more than this tick lets out.
    const double leaving = std::max(0.0, force.dot(velocity) * period_);
    const double excess = std::min(leaving, observer_.out() + leaving - remote_.energyIn());
    if (excess > 0.0)
    {
      damping_ = std::min(params_.passivity_damping_limit, excess / speed2_dt);
      rendered -= damping_ * velocity;
      // Beyond the damper's cap: the push along the motion cut (never reversed).
      const double still = observer_.out() + std::max(0.0, rendered.dot(velocity) * period_) - remote_.energyIn();
      if (still > 0.0 && rendered.dot(velocity) > 0.0)
      {
        const double speed = velocity.norm();
        const double cut = std::min(rendered.dot(velocity) / speed, still / (speed * period_));
        rendered -= (cut / speed) * velocity;
      }
      ++active_ticks_;
    }
  }
  const double length = rendered.norm();
  if (length > max_force)
  {
    rendered *= max_force / length;
  }
  observer_.observe(-rendered.dot(velocity), period_);
  noteMargin();
  return rendered;
}

void DevicePortPassivity::reset()
{
  resetSide();
  damping_ = 0.0;
}

PhysicsPortPassivity::PhysicsPortPassivity(const PassivityParams& params, double period)
    : params_(params), period_(period)
{
  checkPort(params, period, "physics port");
}

void PhysicsPortPassivity::observe(const Eigen::Vector3d& position, const Eigen::Vector3d& force)
{
  if (!force.allFinite() || !position.allFinite())
  {
    return;
  }
  // The force the physics answered with, over the move of the position it was given.
  double work = 0.0;
  if (moves_.work(position, force, &work))
  {
    observer_.observe(work / period_, period_);
  }
  noteMargin();
}

void PhysicsPortPassivity::reset()
{
  resetSide();
  drift_.setZero();
  moves_.reset();
}
}  // namespace god_finger
