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

std::unique_ptr<interactive_markers::InteractiveMarkerServer> makeHandMarker(
    ros::NodeHandle& nh, const std::string& frame, const Eigen::Vector3d& start,
    std::function<void(const HandMarkerPose&)> on_move)
{
  auto server = std::make_unique<interactive_markers::InteractiveMarkerServer>(nh.resolveName("device_marker"));
  visualization_msgs::InteractiveMarker marker;
  marker.header.frame_id = frame;
  marker.name = "hand";
  marker.description = "drag to move the finger, turn a ring to orient it";
  marker.scale = 0.05;
  marker.pose.position.x = start.x();
  marker.pose.position.y = start.y();
  marker.pose.position.z = start.z();
  marker.pose.orientation.w = 1.0;
  visualization_msgs::InteractiveMarkerControl free;
  free.interaction_mode = visualization_msgs::InteractiveMarkerControl::MOVE_3D;
  free.always_visible = true;
  visualization_msgs::Marker ball;
  ball.type = visualization_msgs::Marker::SPHERE;
  ball.scale.x = ball.scale.y = ball.scale.z = 0.012;
  ball.color.r = 0.2f;
  ball.color.g = 0.9f;
  ball.color.b = 0.2f;
  ball.color.a = 0.6f;
  free.markers.push_back(ball);
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
  server->insert(marker,
                 [on_move, rotated](const visualization_msgs::InteractiveMarkerFeedbackConstPtr& feedback) mutable
                 {
                   if (feedback->event_type != visualization_msgs::InteractiveMarkerFeedback::POSE_UPDATE)
                   {
                     return;
                   }
                   const geometry_msgs::Quaternion& q = feedback->pose.orientation;
                   const Eigen::Quaterniond marker_orientation(q.w, q.x, q.y, q.z);
                   // A moved (not turned) marker keeps the identity; a ring's update turns it.
                   rotated = rotated || feedback->control_name.rfind("rotate_", 0) == 0 ||
                             std::abs(std::abs(marker_orientation.w()) - 1.0) > 1e-9;
                   HandMarkerPose pose;
                   pose.position =
                       Eigen::Vector3d(feedback->pose.position.x, feedback->pose.position.y, feedback->pose.position.z);
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
