#include "sleep/hooked_world.h"

#include "sleep/touching_islands.h"

#include <new>

namespace god_finger::internal
{
HookedWorld::HookedWorld(btDispatcher* dispatcher, btBroadphaseInterface* broadphase, btConstraintSolver* solver,
                         btCollisionConfiguration* configuration)
    : btDiscreteDynamicsWorld(dispatcher, broadphase, solver, configuration)
{
  // Islands of touching bodies (touching_islands.h), in Bullet's own storage: the world
  // destroys and frees its island manager as it made it.
  m_islandManager->~btSimulationIslandManager();
  btAlignedFree(m_islandManager);
  m_islandManager = new (btAlignedAlloc(sizeof(TouchingIslands), 16)) TouchingIslands();
}

void HookedWorld::performDiscreteCollisionDetection()
{
  btDiscreteDynamicsWorld::performDiscreteCollisionDetection();
  if (after_collision)
  {
    after_collision();
  }
}

void HookedWorld::predictUnconstraintMotion(btScalar time_step)
{
  for (int i = 0; i < m_nonStaticRigidBodies.size(); ++i)
  {
    btRigidBody* body = m_nonStaticRigidBodies[i];
    if (body->isActive() && !body->isStaticOrKinematicObject())
    {
      body->applyDamping(time_step);
      body->predictIntegratedTransform(time_step, body->getInterpolationWorldTransform());
    }
  }
}

void HookedWorld::updateActivationState(btScalar time_step)
{
  for (int i = 0; i < m_nonStaticRigidBodies.size(); ++i)
  {
    btRigidBody* body = m_nonStaticRigidBodies[i];
    body->updateDeactivation(time_step);
    const int state = body->getActivationState();
    if (state == DISABLE_DEACTIVATION || state == DISABLE_SIMULATION)
    {
      continue;
    }
    const bool wants_sleep =
        state == ISLAND_SLEEPING || state == WANTS_DEACTIVATION || body->getDeactivationTime() > sleep_time;
    if (!wants_sleep)
    {
      body->setActivationState(ACTIVE_TAG);
    }
    else if (state == ACTIVE_TAG)
    {
      body->setActivationState(WANTS_DEACTIVATION);
    }
    else if (state == ISLAND_SLEEPING)
    {
      body->setLinearVelocity(btVector3(0, 0, 0));
      body->setAngularVelocity(btVector3(0, 0, 0));
    }
  }
}
}  // namespace god_finger::internal
