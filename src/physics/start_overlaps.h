// Bodies that start inside one another: a scene whose bodies overlap by more than a contact's
// worth at load (an object placed into the table, two objects at one place) explodes apart on
// the first step, and the user should know which and by how much. Internal to physics.
//
// Units: m, between the shapes the steps collide (near_callback.h: a ball resting in a cup's
// hollow touches its true surface, not the hulls that fill it). Not real-time safe (run once, when
// the world is built); it leaves the world's own pairs and manifolds untouched, so a world
// steps bit for bit as it would without the check.
#pragma once

#include "scene_body.h"

#include "god_finger/scene/scene_description.h"

#include <btBulletCollisionCommon.h>

#include <string>
#include <vector>

namespace god_finger::internal
{
// Bodies penetrate more than this at load: warned about (Bullet's margins and a scene list's
// 0.5 mm placements stay far below it).
constexpr double kStartOverlapDepth = 0.002;  // m

// Two bodies that start inside each other.
struct StartOverlap
{
  int body = -1;       // scene index
  int other = -1;      // scene index, > body
  double depth = 0.0;  // m, > kStartOverlapDepth
};

// Every pair of bodies (at least one of them free, not the two bodies of a joint, which do not
// collide) that start more than kStartOverlapDepth inside each other. `bodies` are in `world`,
// indexed as `scene`'s.
std::vector<StartOverlap> startOverlaps(btCollisionWorld* world, const std::vector<SceneBody>& bodies,
                                        const SceneDescription& scene);
// The line the user reads: both names, the depth, what happens and what to do.
std::string describe(const StartOverlap& overlap, const SceneDescription& scene);
}  // namespace god_finger::internal
