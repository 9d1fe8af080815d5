// A scripted hand: a position that moves in straight lines between timed waypoints.
//
// Units: seconds and metres. Invariants: waypoint times strictly increase; before the first
// waypoint the path is at the first position, after the last at the last one.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace god_finger
{
struct Waypoint
{
  double time = 0.0;                                   // s
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // m
};

// A hand's reach between two times: 0 before `start`, 1 after `end`, between them the
// minimum-jerk profile 10 u^3 - 15 u^4 + 6 u^5 of u = (t - start) / (end - start) (it starts and
// stops with zero velocity and acceleration). Real-time safe.
double minimumJerkRamp(double t, double start, double end);

class WaypointPath
{
 public:
  WaypointPath() = default;
  // Throws InputError if the list is empty, a value is not finite or times do not increase.
  explicit WaypointPath(std::vector<Waypoint> waypoints);
  // Within 1e-9 of a segment from a waypoint (rounding), the waypoint itself, bit for bit.
  Eigen::Vector3d at(double time) const;
  double endTime() const;
  const std::vector<Waypoint>& waypoints() const
  {
    return waypoints_;
  }

 private:
  std::vector<Waypoint> waypoints_;
};
}  // namespace god_finger
