// The ROS side of the pose_source backend (devices/pose_source.h): a geometry_msgs/PoseArray
// subscriber writing a PoseFeed, its i-th pose the i-th finger's (position only, in the device
// frame; the header's frame_id is not transformed). Stamps go onto steadySeconds()' clock: a
// stamp d seconds before ros::Time::now() is d seconds before steadySeconds(); a zero stamp
// means "now" (tools that do not stamp).
#pragma once

#include "god_finger/devices/pose_source.h"

#include <ros/node_handle.h>

#include <memory>
#include <string>

namespace god_finger
{
// Subscribes `feed` to `topic` (resolved in `nh`); the returned handle keeps the subscription,
// which holds the feed weakly.
std::shared_ptr<void> connectPoseFeed(ros::NodeHandle nh, const std::string& topic, std::shared_ptr<PoseFeed> feed);
}  // namespace god_finger
