// The scene a node simulates: its ~scene parameter (a URDF path, required), loaded with ROS's
// package lookup (ros::package::getPath) for package:// mesh names.
#pragma once

#include "god_finger/scene/scene_description.h"

#include <ros/node_handle.h>

#include <string>

namespace god_finger
{
// `path` receives the URDF path. InputError naming the parameter, the file or the link.
SceneDescription loadSceneParameter(const ros::NodeHandle& pnh, std::string* path);
}  // namespace god_finger
