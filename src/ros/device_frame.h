// The transform world -> NAME_device (the workspace mapping's offset and rotation), published as
// a static transform by whichever node owns the device (the haptic node in the topic topologies,
// the servo node in the default one), so that rviz can show what lives in device coordinates:
// the interactive backend's handle. The mapping's scale has no place in a transform: with a scale
// other than 1 the handle shows unscaled.
#pragma once

#include "god_finger/haptics/workspace_mapping.h"

#include <geometry_msgs/TransformStamped.h>
#include <ros/time.h>

#include <string>

namespace god_finger
{
inline geometry_msgs::TransformStamped deviceFrameTransform(const WorkspaceMappingParams& mapping,
                                                            const std::string& device_frame, const ros::Time& stamp)
{
  geometry_msgs::TransformStamped transform;
  transform.header.stamp = stamp;
  transform.header.frame_id = "world";
  transform.child_frame_id = device_frame;
  transform.transform.translation.x = mapping.offset.x();
  transform.transform.translation.y = mapping.offset.y();
  transform.transform.translation.z = mapping.offset.z();
  transform.transform.rotation.x = mapping.rotation.x();
  transform.transform.rotation.y = mapping.rotation.y();
  transform.transform.rotation.z = mapping.rotation.z();
  transform.transform.rotation.w = mapping.rotation.w();
  return transform;
}
}  // namespace god_finger
