#include "god_finger/haptics/orientation_path.h"

#include "god_finger/support/input_error.h"

#include <cmath>
#include <string>

namespace god_finger
{
bool usableOrientation(const Eigen::Quaterniond& orientation)
{
  const double norm = orientation.norm();
  return orientation.coeffs().allFinite() && norm >= 0.5 && norm <= 2.0;
}

OrientationPath::OrientationPath(std::vector<OrientationWaypoint> waypoints) : waypoints_(std::move(waypoints))
{
  if (waypoints_.empty())
  {
    throw InputError("orientation path: needs at least one waypoint");
  }
  for (std::size_t i = 0; i < waypoints_.size(); ++i)
  {
    OrientationWaypoint& waypoint = waypoints_[i];
    if (!std::isfinite(waypoint.time) || !usableOrientation(waypoint.orientation))
    {
      throw InputError("orientation path: waypoint " + std::to_string(i) +
                       " needs a finite time and a finite quaternion of norm in [0.5, 2]");
    }
    if (i > 0 && !(waypoint.time > waypoints_[i - 1].time))
    {
      throw InputError("orientation path: waypoint " + std::to_string(i) + " is not later than the one before");
    }
    waypoint.orientation.normalize();
  }
}

Eigen::Quaterniond OrientationPath::at(double time) const
{
  if (!(time > waypoints_.front().time))
  {
    return waypoints_.front().orientation;
  }
  for (std::size_t i = 1; i < waypoints_.size(); ++i)
  {
    if (time < waypoints_[i].time)
    {
      const OrientationWaypoint& a = waypoints_[i - 1];
      const OrientationWaypoint& b = waypoints_[i];
      return a.orientation.slerp((time - a.time) / (b.time - a.time), b.orientation);
    }
  }
  return waypoints_.back().orientation;
}
}  // namespace god_finger
