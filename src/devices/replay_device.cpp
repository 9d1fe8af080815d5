#include "god_finger/devices/replay_device.h"

namespace god_finger
{
DeviceReading ReplayDevice::update(double time, const Eigen::Vector3d&)
{
  if (!start_set_)
  {
    start_ = time;
    start_set_ = true;
  }
  const double t = time - start_;
  constexpr double kVelocityWindow = 1e-3;  // s: the velocity is the slope over the last 1 ms
  DeviceReading reading;
  reading.position = track_.at(t);
  reading.velocity = (reading.position - track_.at(t - kVelocityWindow)) / kVelocityWindow;
  return reading;
}
}  // namespace god_finger
