// Scene edits while the world runs (GodFingerWorld::addObject, removeObject): the scene that
// results, and the edit made in Bullet's live world: the new bodies (and their joints) added, the
// removed ones (and the joints that hold them) taken out; nothing else is rebuilt. Internal to
// physics.
//
// What an edit keeps: every other body's Bullet body, where it is and moving as it moved; Bullet's
// broadphase pairs and contact manifolds between the bodies it did not touch, with their points
// and applied impulses (the next step's warm start: a loaded stack steps bit for bit as without
// the edit); sleep (dormant bodies stay out of the world, with their groups and the contacts they
// slept on); the joints between kept bodies (their constraints); every proxy whole (its Bullet
// body, coupling, target, orientation, let-go, overlap push), its per-body state (radial basis,
// warm starts, pads) carried to the bodies' new indices; soft bodies' volumes as they are; the
// time and step count.
// What it drops: a removed body's pairs and manifolds (Bullet's removeRigidBody cleans its pairs),
// the contacts sleepers saved with it, and the proxies' contact list of the last step (numbered in
// the old scene: found again by the next step). What it wakes: a removed body's sleep group and
// every dormant body within Bullet's contact threshold of it (what rested on it falls). A body
// whose joint went may sleep from now on. A proxy that pressed a removed body lets go over
// WorldParams::let_go_time. Every case is done in place (the table going too: what slept on it
// wakes; the soft bodies' supports are placed again when a static body comes or goes); only a
// reset rebuilds Bullet's world.
//
// Renumbering (body i of the new scene was old_of_new[i]): the bodies' user index 2, sleep's
// per-body vectors, dormant tree and slept contacts (world_sleep.h remapSleep), the jointed flags
// and joints' constraints (in the new scene's joint order), the soft bodies' list, the proxies'
// per-body vectors (proxy.h remapBodies). Bodies' user pointers (their finger surfaces) move with
// their SceneBody and need none. Bullet's world order: new bodies after the proxies (a reset
// rebuilds it in scene order).
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

// The world edited into `next`: old_of_new[i] is the body of now that becomes next's body i, or -1
// for a new one, taken in order from `made` (next's new bodies, made beforehand) or made here when
// `made` is null. next's joints are the joints of now whose bodies stay, in their order, then the
// new ones (as sceneWithObject and sceneWithout make them). InputError before anything changes
// when a new body cannot be made.
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
