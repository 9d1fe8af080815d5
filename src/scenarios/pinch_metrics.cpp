#include "god_finger/scenarios/pinch_metrics.h"

#include <algorithm>

namespace god_finger
{
PinchMetrics::PinchMetrics(int object, const ScenarioTimes& times, const BodyState& start, bool turn)
    : object_(object), times_(times), start_height_(start.center_of_mass.z()), measure_turn_(turn)
{
}

void PinchMetrics::add(double time, const GodFingerWorld& world)
{
  if (world.interfaceCount() < 2 || time < times_.lift_start)
  {
    return;
  }
  const BodyState object = world.bodyState(object_);
  const Eigen::Vector3d grip = 0.5 * (world.interfaceState(0).proxy_position + world.interfaceState(1).proxy_position);
  const Eigen::Quaterniond orientation(object.pose.linear());
  if (!gripped_)
  {
    gripped_ = true;
    grip_on_object_ = object.pose.inverse() * grip;
    grip_orientation_ = orientation;
  }
  slip_ = std::max(slip_, (object.pose * grip_on_object_ - grip).norm());
  turn_ = std::max(turn_, orientation.angularDistance(grip_orientation_));
  if (time >= times_.lift_end && object.center_of_mass.z() - start_height_ < 0.5 * times_.lift_height)
  {
    held_ = false;
  }
}

std::map<std::string, double> PinchMetrics::metrics() const
{
  std::map<std::string, double> result{{"held", gripped_ && held_ ? 1.0 : 0.0}, {"slip_m", slip_}};
  if (measure_turn_)
  {
    result["turn_rad"] = turn_;
  }
  return result;
}
}  // namespace god_finger
