// The set-up every operator task (grip, sheet push, cylinder turn, mug grasp) starts with: its
// squeeze (or press) checked against its range, then its scene built, in a world with the task's
// parameters and contact model, and the index of the body it watches. Private to the scenarios.
//
// Units: SI. Not real-time (builds a world).
#pragma once

#include "god_finger/physics/god_finger_world.h"
#include "god_finger/support/input_error.h"
#include "god_finger/support/text_numbers.h"

#include <functional>
#include <string>

namespace god_finger
{
struct TaskWorld
{
  // Throws InputError "TASK: WHAT VALUE m is outside (0, LARGEST]" unless 0 < value <= largest,
  // before the scene is built; then whatever the scene, the world or the lookup throws (a body
  // `object` the scene lacks: InputError naming it).
  TaskWorld(const std::string& task, const std::string& what, double value, double largest,
            const std::function<SceneDescription()>& make_scene, const WorldParams& params, ContactModel model,
            const std::string& object)
      : scene(checkedScene(task, what, value, largest, make_scene)), world(scene, params), object(scene.find(object))
  {
    world.setContactModel(model);
    if (this->object < 0)
    {
      throw InputError(task + ": the scene has no body '" + object + "'");
    }
  }

  SceneDescription scene;
  GodFingerWorld world;
  int object = -1;

 private:
  static SceneDescription checkedScene(const std::string& task, const std::string& what, double value, double largest,
                                       const std::function<SceneDescription()>& make_scene)
  {
    if (!(value > 0.0 && value <= largest))
    {
      throw InputError(task + ": " + what + " " + std::to_string(value) + " m is outside (0, " + jsonNumber(largest) +
                       "]");
    }
    return make_scene();
  }
};
}  // namespace god_finger
