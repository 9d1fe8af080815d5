#include "hand_marker.h"
#include "node_parameters.h"

#include "god_finger/support/text_numbers.h"
#include "parameters.h"

#include <ros/ros.h>

#include <cmath>

namespace god_finger
{
Eigen::Quaterniond fingerOrientationOfMarker(const Eigen::Quaterniond& marker)
{
  return (marker * Eigen::Quaterniond(0.0, 1.0, 0.0, 0.0)).normalized();  // (w, x, y, z): 180 deg about x
}

namespace
{
constexpr uint32_t kBackToStart = 1;  // the menu entry's id

geometry_msgs::Pose poseAt(const Eigen::Vector3d& position, const geometry_msgs::Quaternion& orientation)
{
  geometry_msgs::Pose pose;
  pose.position.x = position.x();
  pose.position.y = position.y();
  pose.position.z = position.z();
  pose.orientation = orientation;
  return pose;
}
}  // namespace

Eigen::Vector3d clampToWorkspace(const Eigen::Vector3d& position, double workspace_radius)
{
  if (!position.allFinite())
  {
    return Eigen::Vector3d::Zero();
  }
  const double distance = position.norm();
  return distance <= workspace_radius ? position : Eigen::Vector3d(position * (workspace_radius / distance));
}

std::unique_ptr<interactive_markers::InteractiveMarkerServer> makeHandMarker(
    ros::NodeHandle& nh, const std::string& frame, const Eigen::Vector3d& start_wanted, double workspace_radius,
    std::function<void(const HandMarkerPose&)> on_move)
{
  const Eigen::Vector3d start = clampToWorkspace(start_wanted, workspace_radius);
  auto server = std::make_unique<interactive_markers::InteractiveMarkerServer>(nh.resolveName("device_marker"));
  visualization_msgs::InteractiveMarker marker;
  marker.header.frame_id = frame;
  marker.name = "hand";
  marker.description = "finger: drag, turn a ring; right-click: back to the start";
  marker.scale = 0.045;
  const Eigen::Vector3d up(0.0, 0.0, kHandleAboveFinger);
  marker.pose = poseAt(start + up, geometry_msgs::Quaternion());
  marker.pose.orientation.w = 1.0;
  nh.setParam("device_marker/handle_height", kHandleAboveFinger);
  marker.pose.orientation.w = 1.0;
  visualization_msgs::MenuEntry back;
  back.id = kBackToStart;
  back.title = "back to the start";
  back.command_type = visualization_msgs::MenuEntry::FEEDBACK;
  marker.menu_entries.push_back(back);
  visualization_msgs::InteractiveMarkerControl free;
  free.interaction_mode = visualization_msgs::InteractiveMarkerControl::MOVE_3D;
  free.always_visible = true;
  visualization_msgs::Marker ball;
  ball.type = visualization_msgs::Marker::SPHERE;
  ball.scale.x = ball.scale.y = ball.scale.z = 0.014;
  // Magenta: nothing else in the views has it, so the grab point is found at a glance (and by
  // the screenshot test).
  ball.color.r = 0.9f;
  ball.color.g = 0.2f;
  ball.color.b = 0.9f;
  ball.color.a = 1.0f;
  free.markers.push_back(ball);
  // The stem down to the finger, vertical whatever the rings turn (FIXED): the finger is at its
  // foot, clear of the rings.
  free.orientation_mode = visualization_msgs::InteractiveMarkerControl::FIXED;
  visualization_msgs::Marker stem;
  stem.type = visualization_msgs::Marker::LINE_LIST;
  stem.scale.x = 0.0015;
  stem.color.g = 0.9f;
  stem.color.r = stem.color.b = 0.2f;
  stem.color.a = 0.8f;
  stem.points.resize(2);
  stem.points[1].z = -kHandleAboveFinger;
  free.markers.push_back(stem);
  marker.controls.push_back(free);
  const double axes[3][4] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}};  // quaternions x, y, z of each arrow pair
  const char* names[3] = {"x", "z", "y"};
  for (int i = 0; i < 3; ++i)
  {
    for (const bool rotate : {false, true})
    {
      visualization_msgs::InteractiveMarkerControl axis;
      axis.name = std::string(rotate ? "rotate_" : "move_") + names[i];
      axis.orientation.w = axes[i][3] / std::sqrt(2.0);
      axis.orientation.x = axes[i][0] / std::sqrt(2.0);
      axis.orientation.y = axes[i][1] / std::sqrt(2.0);
      axis.orientation.z = axes[i][2] / std::sqrt(2.0);
      axis.interaction_mode = rotate ? visualization_msgs::InteractiveMarkerControl::ROTATE_AXIS
                                     : visualization_msgs::InteractiveMarkerControl::MOVE_AXIS;
      marker.controls.push_back(axis);
    }
  }
  bool rotated = false;  // the server calls back from one thread
  interactive_markers::InteractiveMarkerServer* raw_server = server.get();
  server->insert(
      marker,
      [on_move, rotated, raw_server, start, up,
       workspace_radius](const visualization_msgs::InteractiveMarkerFeedbackConstPtr& feedback) mutable
      {
        using Feedback = visualization_msgs::InteractiveMarkerFeedback;
        const bool back_to_start =
            feedback->event_type == Feedback::MENU_SELECT && feedback->menu_entry_id == kBackToStart;
        if (feedback->event_type != Feedback::POSE_UPDATE && !back_to_start)
        {
          return;
        }
        const Eigen::Vector3d dragged =
            Eigen::Vector3d(feedback->pose.position.x, feedback->pose.position.y, feedback->pose.position.z) - up;
        const Eigen::Vector3d position = back_to_start ? start : clampToWorkspace(dragged, workspace_radius);
        if (back_to_start || position != dragged)
        {
          // rviz shows the handle where the finger is (after the drag, if one goes on).
          raw_server->setPose(feedback->marker_name, poseAt(position + up, feedback->pose.orientation));
          raw_server->applyChanges();
        }
        const geometry_msgs::Quaternion& q = feedback->pose.orientation;
        const Eigen::Quaterniond marker_orientation(q.w, q.x, q.y, q.z);
        // A moved (not turned) marker keeps the identity; a ring's update turns it.
        rotated = rotated || feedback->control_name.rfind("rotate_", 0) == 0 ||
                  std::abs(std::abs(marker_orientation.w()) - 1.0) > 1e-9;
        HandMarkerPose pose;
        pose.position = position;
        if (rotated && marker_orientation.coeffs().allFinite() && marker_orientation.norm() > 0.5)
        {
          pose.rotated = true;
          pose.orientation = fingerOrientationOfMarker(marker_orientation.normalized());
        }
        on_move(pose);
      });
  server->applyChanges();
  return server;
}

double sharedScriptStart(const ros::NodeHandle& pnh, double clock_now)
{
  const double delay = readNodeParams(pnh).script_delay;
  std::string epoch_text;
  double epoch = 0.0;
  if (ros::param::get("/god_finger_script_epoch", epoch_text) &&
      parseDouble(epoch_text.substr(0, epoch_text.find_last_not_of(" \n\r\t") + 1), &epoch))
  {
    return clock_now + epoch + delay - ros::WallTime::now().toSec();
  }
  if (ros::param::get("/god_finger_script_epoch", epoch))
  {
    return clock_now + epoch + delay - ros::WallTime::now().toSec();
  }
  return NAN;
}
}  // namespace god_finger
