// The interactive backend's hand: an rviz interactive marker in the device frame (a sphere
// moved freely in the view plane, and arrows along each axis). `on_move` gets every dragged
// position (m, device frame), in the marker server's thread.
#pragma once

#include <interactive_markers/interactive_marker_server.h>
#include <ros/node_handle.h>

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>

namespace god_finger
{
// The server is `nh`'s device_marker (rviz: InteractiveMarkers, NAME/device_marker/update).
std::unique_ptr<interactive_markers::InteractiveMarkerServer> makeHandMarker(
    ros::NodeHandle& nh, const std::string& frame, const Eigen::Vector3d& start,
    std::function<void(const Eigen::Vector3d&)> on_move);

// When the scripts of the launch's simulated devices start, on a clock that reads `clock_now`
// (s) now: the launch's /god_finger_script_epoch (wall clock) plus ~script_delay (`pnh`);
// NaN without an epoch.
double sharedScriptStart(const ros::NodeHandle& pnh, double clock_now);
}  // namespace god_finger
