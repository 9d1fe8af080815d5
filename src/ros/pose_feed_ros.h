// The ROS side of the pose_source backend (devices/pose_source.h), writing its PoseFeed from
//  - a geometry_msgs/PoseArray topic (params.topic, in the interface's namespace): its i-th
//    pose is the i-th finger's (position only; the header's frame_id is not transformed); or
//  - TF (params.frames non-empty): each finger's frame looked up in params.reference_frame,
//    the newest transform, polled at params.poll_rate (a frame TF does not have is not
//    refreshed).
// Stamps go onto steadySeconds()' clock: a stamp d seconds before ros::Time::now() is d seconds
// before steadySeconds(); a zero stamp means now (tools that do not stamp).
#pragma once

#include "god_finger/devices/pose_source.h"

#include <ros/node_handle.h>

#include <memory>

namespace god_finger
{
// Starts feeding `feed`; the returned handle keeps the subscription (or the TF listener and its
// timer), which holds the feed weakly.
std::shared_ptr<void> connectPoseFeed(ros::NodeHandle nh, const PoseSourceParams& params,
                                      std::shared_ptr<PoseFeed> feed);
}  // namespace god_finger
