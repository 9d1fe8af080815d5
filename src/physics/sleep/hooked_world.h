// Bullet's discrete dynamics world with what GodFingerWorld adds to its step: a hook between
// collision detection and the solver (where contact areas join the solver), islands of touching
// bodies (touching_islands.h), motion predicted for awake bodies only, and sleeping decided with
// this world's own time (Bullet's is one global, gDeactivationTime). Internal to physics.
//
// Units: SI (s). Not real-time safe to construct; stepping allocates nothing beyond Bullet's own.
#pragma once

#include <btBulletDynamicsCommon.h>

#include <functional>

namespace god_finger::internal
{
class HookedWorld : public btDiscreteDynamicsWorld
{
 public:
  HookedWorld(btDispatcher* dispatcher, btBroadphaseInterface* broadphase, btConstraintSolver* solver,
              btCollisionConfiguration* configuration);
  // Runs after Bullet's collision detection, before the islands and the solver.
  std::function<void()> after_collision;
  double sleep_time = 0.0;  // s, SleepParams::time; 0: bodies carry DISABLE_DEACTIVATION
  void performDiscreteCollisionDetection() override;

 protected:
  // Bullet's, for awake bodies only: Bullet predicts every dynamic body's motion each step, and
  // for a sleeping body (zero velocity) that was a fifth of a 1000-box table's step.
  void predictUnconstraintMotion(btScalar time_step) override;
  // Bullet's rule (btDiscreteDynamicsWorld::updateActivationState) with sleep_time for
  // gDeactivationTime: a body slow for longer wants to sleep; its island (simulation island
  // manager, next step) sleeps when every body in it wants to; a sleeping body keeps zero
  // velocity.
  void updateActivationState(btScalar time_step) override;
};
}  // namespace god_finger::internal
