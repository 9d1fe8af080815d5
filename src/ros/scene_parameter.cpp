#include "scene_parameter.h"

#include "god_finger/support/input_error.h"
#include "god_finger/scene/scene_file.h"
#include "parameters.h"

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
  return loadScene(*path, [](const std::string& name) { return ros::package::getPath(name); });
}
}  // namespace god_finger
