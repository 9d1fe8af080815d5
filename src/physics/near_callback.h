// The world's Bullet near callback: which shapes a broadphase pair's narrowphase collides.
// - A pair of sleeping (or static) bodies is skipped first: a resting table of 1000 boxes has
//   1000 such pairs, visited every step. So is a pair of static or kinematic ones (a resting
//   soft body, kinematic, against the table it stands on: its own support holds it).
// - A finger (proxy) against a body with a FingerSurface (scene_body.h) collides with that
//   surface, the body's true one, not with its hulls: a finger enters a cup and presses the
//   floor of a plate, and its contact point lies on the walk mesh. So does a free convex body
//   (a ball dropped into a cup rests on its inner floor); supports (static bodies) and other
//   bodies with a FingerSurface touch it through its hulls.
// - Every other pair collides through its collision shapes, as Bullet's default does.
// The manifolds are the pair's collision objects' in every case, so the solver's impulses reach
// the body itself. Internal to physics. Real-time safe (no allocation once a pair's algorithm
// exists; Bullet creates it on the pair's first overlap, from its pools).
#pragma once

#include <btBulletCollisionCommon.h>

namespace god_finger::internal
{
void worldNearCallback(btBroadphasePair& pair, btCollisionDispatcher& dispatcher, const btDispatcherInfo& info);

// How deep (m, >= 0) `a` and `b` penetrate, by Bullet's contact test (world->contactPairTest)
// with the shapes the near callback collides for that pair: a finger (or a probe tagged
// kKindProxy) against a body's FingerSurface. For the checks made when the world is built or a
// finger added (a body starting inside another, a finger starting inside a body), which must see
// what the steps will. Not real-time safe.
double deepestPenetrationAsCollided(btCollisionWorld* world, btCollisionObject* a, btCollisionObject* b);
}  // namespace god_finger::internal
