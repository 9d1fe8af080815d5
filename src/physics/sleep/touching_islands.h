// Simulation islands from touching contacts (Box2D's rule) instead of Bullet's overlapping
// bounding boxes. Internal to physics.
//
// Bullet unites two dynamic bodies into one island when their broadphase boxes overlap, and
// btDbvtBroadphase fattens every box by 5 cm plus the 2 cm contact threshold: a grid of 4 cm boxes
// 8 cm apart is one island, so a finger on one box kept all of them awake, and a proxy woke a
// stack from 10 cm away. Here two bodies share an island only while their manifold holds a contact
// point (within Bullet's contact threshold, 2 cm): what touches, or is about to. Sleeping bodies
// keep their manifolds, so a stack that fell asleep together wakes together.
//
// Island tags are assigned exactly as Bullet's (static and kinematic objects get none). Not
// real-time safe to construct; updating allocates nothing once the union-find has grown to the
// body count.
#pragma once

#include <BulletCollision/CollisionDispatch/btSimulationIslandManager.h>

namespace god_finger::internal
{
class TouchingIslands : public btSimulationIslandManager
{
 public:
  void updateActivationState(btCollisionWorld* world, btDispatcher* dispatcher) override;
};
}  // namespace god_finger::internal
