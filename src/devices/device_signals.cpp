#include "god_finger/devices/device_signals.h"

#include "god_finger/devices/vendor_frames.h"

namespace god_finger
{
std::array<double, 3> deviceForceToVendorAxes(const Eigen::Vector3d& force)
{
  const Eigen::Vector3d vendor = hdFrame().toVendor(force);
  return {vendor.x(), vendor.y(), vendor.z()};
}

Eigen::Vector3d motorCommand(const Eigen::Vector3d& force, double max_force)
{
  if (!force.allFinite())
  {
    return Eigen::Vector3d::Zero();
  }
  const double magnitude = force.norm();
  return magnitude > max_force ? Eigen::Vector3d(force * (max_force / magnitude)) : force;
}

Eigen::Vector3d VelocityEstimator::update(double time, const Eigen::Vector3d& position)
{
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  if (have_last_ && time > last_time_)
  {
    velocity = (position - last_position_) / (time - last_time_);
  }
  have_last_ = true;
  last_time_ = time;
  last_position_ = position;
  return velocity;
}
}  // namespace god_finger
