#include "solver/finger_contact_friction.h"

#include "bullet_helpers.h"

#include <BulletCollision/CollisionDispatch/btManifoldResult.h>

namespace god_finger::internal
{
namespace
{
btScalar fingerRollingFriction(const btCollisionObject* body0, const btCollisionObject* body1)
{
  if (body0->getUserIndex() == kKindProxy)
  {
    return body0->getRollingFriction();
  }
  if (body1->getUserIndex() == kKindProxy)
  {
    return body1->getRollingFriction();
  }
  return btManifoldResult::calculateCombinedRollingFriction(body0, body1);
}
}  // namespace

void useFingerRollingFriction()
{
  gCalculateCombinedRollingFrictionCallback = &fingerRollingFriction;
}
}  // namespace god_finger::internal
