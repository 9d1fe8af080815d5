#include "god_finger/haptics/waypoint_path.h"

#include <algorithm>

#include "god_finger/support/input_error.h"

#include <cmath>
#include <string>

namespace god_finger
{
WaypointPath::WaypointPath(std::vector<Waypoint> waypoints) : waypoints_(std::move(waypoints))
{
  if (waypoints_.empty())
  {
    throw InputError("waypoint path: no waypoints");
  }
  for (std::size_t i = 0; i < waypoints_.size(); ++i)
  {
    if (!std::isfinite(waypoints_[i].time) || !waypoints_[i].position.allFinite())
    {
      throw InputError("waypoint path: waypoint " + std::to_string(i) + " is not finite");
    }
    if (i > 0 && !(waypoints_[i].time > waypoints_[i - 1].time))
    {
      throw InputError("waypoint path: waypoint " + std::to_string(i) +
                       " at t = " + std::to_string(waypoints_[i].time) + " s does not come after the previous one");
    }
  }
}

Eigen::Vector3d WaypointPath::at(double time) const
{
  if (time <= waypoints_.front().time)
  {
    return waypoints_.front().position;
  }
  for (std::size_t i = 1; i < waypoints_.size(); ++i)
  {
    if (time < waypoints_[i].time)
    {
      const Waypoint& a = waypoints_[i - 1];
      const Waypoint& b = waypoints_[i];
      const double s = (time - a.time) / (b.time - a.time);
      // At a waypoint up to rounding (a recorded track replayed on the same ticks): the
      // waypoint itself, bit for bit, not an interpolation 1e-16 off it.
      constexpr double kAtWaypoint = 1e-9;
      if (s < kAtWaypoint)
      {
        return a.position;
      }
      if (s > 1.0 - kAtWaypoint)
      {
        return b.position;
      }
      return a.position + s * (b.position - a.position);
    }
  }
  return waypoints_.back().position;
}

double WaypointPath::endTime() const
{
  return waypoints_.back().time;
}
double minimumJerkRamp(double t, double start, double end)
{
  const double u = std::clamp((t - start) / (end - start), 0.0, 1.0);
  return u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
}
}  // namespace god_finger
