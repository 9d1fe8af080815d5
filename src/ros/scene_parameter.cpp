#include "scene_parameter.h"

#include "god_finger/scene/scene_file.h"
#include "god_finger/support/input_error.h"
#include "parameters.h"

#include <ros/console.h>
#include <ros/package.h>

namespace god_finger
{
SceneDescription loadSceneParameter(const ros::NodeHandle& pnh, std::string* path)
{
  *path = readString(pnh, "scene", "");
  if (path->empty())
  {
    throw InputError("parameter '" + pnh.resolveName("scene") +
                     "' is required (the scene's file: a URDF, an object's URDF or a scene list)");
  }
  SceneDescription scene = loadScene(*path, [](const std::string& name) { return ros::package::getPath(name); });
  for (const std::string& warning : scene.warnings)
  {
    ROS_WARN("%s", warning.c_str());
  }
  return scene;
}

std::unique_ptr<GodFingerWorld> loadSceneWorld(const ros::NodeHandle& pnh, const WorldParams& params, std::string* path)
{
  auto world = std::make_unique<GodFingerWorld>(loadSceneParameter(pnh, path), params);
  for (const std::string& warning : world->startWarnings())
  {
    ROS_WARN("scene '%s': %s", path->c_str(), warning.c_str());
  }
  return world;
}
}  // namespace god_finger
