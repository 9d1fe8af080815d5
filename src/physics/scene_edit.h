// Scene edits while the world runs (GodFingerWorld::addObject, removeObject): the scene that
// results, and Bullet's world rebuilt around it. Internal to physics.
//
// What an edit keeps: every other body where it is and moving as it moved; every proxy whole (its
// Bullet body, coupling, target, orientation, let-go, overlap push), its per-body state (radial
// basis, warm starts, pads) carried to the bodies' new indices; the time and step count. What it
// drops: Bullet's own contact manifolds (one step without their warm start) and sleep (sleeping
// bodies wake and sleep again). A proxy that pressed a removed body lets go over
// WorldParams::let_go_time.
// Not real-time safe: it allocates and may make bodies' shapes.
#pragma once

#include "scene_body.h"

#include "god_finger/scene/scene_description.h"

#include <string>
#include <vector>

namespace god_finger::internal
{
struct WorldCore;

// A finger whose proxy starts inside a body that was just added.
struct ProxyInsideAdded
{
  int finger = -1;
  int body = -1;       // scene index
  double depth = 0.0;  // m
};
std::string describe(const ProxyInsideAdded& inside, const SceneDescription& scene);

// The world around `next`: old_of_new[i] is the body of now that becomes next's body i, or -1 for
// a new one, taken in order from `made` (next's new bodies, made beforehand) or made here when
// `made` is null. InputError before anything changes when a new body cannot be made.
void changeScene(WorldCore* core, SceneDescription next, const std::vector<int>& old_of_new,
                 std::vector<SceneBody>* made);
// The scene with `object`'s bodies and joints appended (its joints re-indexed), checked; and
// old_of_new for changeScene. InputError, nothing changed: a name the scene has already, a scene
// the world cannot take.
SceneDescription sceneWithObject(const WorldCore& core, const SceneDescription& object, std::vector<int>* old_of_new);
// The scene without the bodies named `name` or `name/...` and the joints that hold them; and
// old_of_new. InputError: no such body.
SceneDescription sceneWithout(const WorldCore& core, const std::string& name, std::vector<int>* old_of_new);
// After an add whose bodies start at scene index `first`: the proxies that start more than
// kStartOverlapDepth inside them (start_overlaps.h).
std::vector<ProxyInsideAdded> proxiesInsideAdded(const WorldCore& core, int first);
}  // namespace god_finger::internal
