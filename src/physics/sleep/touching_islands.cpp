#include "sleep/touching_islands.h"

#include <BulletCollision/BroadphaseCollision/btDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionWorld.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

namespace god_finger::internal
{
void TouchingIslands::updateActivationState(btCollisionWorld* world, btDispatcher* dispatcher)
{
  int index = 0;
  btCollisionObjectArray& objects = world->getCollisionObjectArray();
  for (int i = 0; i < objects.size(); ++i)
  {
    btCollisionObject* object = objects[i];
    if (!object->isStaticOrKinematicObject())
    {
      object->setIslandTag(index++);
    }
    object->setCompanionId(-1);
    object->setHitFraction(1.0);
  }
  initUnionFind(index);
  const int manifolds = dispatcher->getNumManifolds();
  for (int m = 0; m < manifolds; ++m)
  {
    const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    const btCollisionObject* a = manifold->getBody0();
    const btCollisionObject* b = manifold->getBody1();
    if (manifold->getNumContacts() > 0 && a->mergesSimulationIslands() && b->mergesSimulationIslands())
    {
      getUnionFind().unite(a->getIslandTag(), b->getIslandTag());
    }
  }
}
}  // namespace god_finger::internal
