// The interactive backend's hand: an rviz interactive marker in the device frame (a sphere
// moved freely in the view plane, arrows along each axis, and rings turning it about each
// axis). `on_move` gets every dragged pose, in the marker server's thread.
//
// The marker's orientation is the finger's with its pulp down: at the start (the marker
// aligned with the device frame) the finger lies along device x with its pulp facing -z (the
// finger frame of physics/oriented_finger.h is the marker's turned 180 degrees about x), and
// the ring about x (rotate_x) rolls the finger about its own axis. Until the user first turns
// a ring the poses carry no orientation (rotated false: the finger stays 3-DOF, as before the
// rings existed); from then on every pose carries one.
//
// The handle (its grab ball, arrows and rings) floats kHandleAboveFinger above the finger, on a
// vertical stem whose foot is the finger: the rings never hide the contact area under the
// finger. The marker's pose is the handle's; the finger's position is the handle's minus the
// height (device frame), published as the parameter NAME/device_marker/handle_height (m).
//
// The handle stays in the device's workspace (the profile's workspace_radius about the device
// origin, haptics/workspace_bound.h): a drag beyond it is answered with the handle put back on
// the workspace's edge (rviz draws it there once the mouse is released), so no drag, however
// wild (rviz's shift-drag moves along the view axis, and fast), can throw it out of reach. Its
// right-click menu has "back to the start", which puts the handle where it began.
#pragma once

#include <interactive_markers/interactive_marker_server.h>
#include <ros/node_handle.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>
#include <memory>
#include <string>

namespace god_finger
{
// m, device frame +z: how far the handle floats above the finger it moves.
constexpr double kHandleAboveFinger = 0.08;

// A dragged marker's pose, in the device frame.
struct HandMarkerPose
{
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // m
  bool rotated = false;  // a ring was turned since the marker was made: `orientation` is valid
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // the finger frame (unit)
};

// The finger frame in the device frame for a handle at `marker` (the marker's orientation in
// the device frame): `marker` turned 180 degrees about its x (the pulp faces the marker's -z).
Eigen::Quaterniond fingerOrientationOfMarker(const Eigen::Quaterniond& marker);

// The point within `workspace_radius` (m) of the device origin nearest `position` (m, device
// frame): `position` itself inside, else on the edge. A non-finite position gives the origin.
Eigen::Vector3d clampToWorkspace(const Eigen::Vector3d& position, double workspace_radius);

// The server is `nh`'s device_marker (rviz: InteractiveMarkers, NAME/device_marker/update). The
// handle starts at `start` (m, device frame; clamped into the workspace) and stays within
// `workspace_radius` (m) of the device origin.
std::unique_ptr<interactive_markers::InteractiveMarkerServer> makeHandMarker(
    ros::NodeHandle& nh, const std::string& frame, const Eigen::Vector3d& start, double workspace_radius,
    std::function<void(const HandMarkerPose&)> on_move);

// When the scripts of the launch's simulated devices start, on a clock that reads `clock_now`
// (s) now: the launch's /god_finger_script_epoch (wall clock) plus ~script_delay (`pnh`);
// NaN without an epoch.
double sharedScriptStart(const ros::NodeHandle& pnh, double clock_now);
}  // namespace god_finger
