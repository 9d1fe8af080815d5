// The scene a node simulates: its ~scene parameter (a URDF path, required), loaded with ROS's
// package lookup (ros::package::getPath) for package:// mesh names.
#pragma once

#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/scene_description.h"

#include <ros/node_handle.h>

#include <memory>
#include <string>

namespace god_finger
{
// `path` receives the URDF path. InputError naming the parameter, the file or the link.
SceneDescription loadSceneParameter(const ros::NodeHandle& pnh, std::string* path);
// The world of that scene with `params`; the loader's warnings and the world's (bodies that
// start inside one another) are printed with ROS_WARN, one line each.
std::unique_ptr<GodFingerWorld> loadSceneWorld(const ros::NodeHandle& pnh, const WorldParams& params,
                                               std::string* path);
}  // namespace god_finger
