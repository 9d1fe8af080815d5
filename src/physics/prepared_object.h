// What PreparedObject (god_finger_world.h) holds: an object's bodies made beforehand. Internal to
// physics.
#pragma once

#include "scene_body.h"

#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/scene_description.h"

#include <vector>

namespace god_finger
{
struct PreparedObject::Impl
{
  SceneDescription object;
  std::vector<internal::SceneBody> bodies;  // by object body index; empty once added
  double max_edge = 0.0;                    // m: the walk edge the bodies were made with
};
}  // namespace god_finger
