// A scripted finger orientation against time: waypoints (time s, unit quaternion of the finger
// frame in the world, oriented_finger.h), spherical linear interpolation between them (the
// shorter way), held before the first and after the last. The orientation counterpart of
// haptics/waypoint_path.h, for scripts that orient their fingers (the roll_finger scenario).
//
// Invariants: at least one waypoint, times finite and strictly increasing, orientations finite
// with a norm in [0.5, 2] (stored normalised). at() is real-time safe.
#pragma once

#include <Eigen/Geometry>
#include <vector>

namespace god_finger
{
// What every orientation a finger is given must be (a path's waypoint, a device's reading, a
// world target): a finite quaternion of norm in [0.5, 2], normalised where used. Real-time safe.
bool usableOrientation(const Eigen::Quaterniond& orientation);

struct OrientationWaypoint
{
  double time = 0.0;  // s
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

class OrientationPath
{
 public:
  // Throws InputError naming the first bad waypoint.
  explicit OrientationPath(std::vector<OrientationWaypoint> waypoints);
  Eigen::Quaterniond at(double time) const;

 private:
  std::vector<OrientationWaypoint> waypoints_;
};
}  // namespace god_finger
