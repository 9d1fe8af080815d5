#include "world_bounds.h"

#include "bullet_helpers.h"

namespace god_finger::internal
{
Eigen::AlignedBox3d worldBounds(const Eigen::AlignedBox3d& scene_box, double margin)
{
  const Eigen::Vector3d grow = Eigen::Vector3d::Constant(margin);
  return Eigen::AlignedBox3d(scene_box.min() - grow, scene_box.max() + grow);
}

bool outsideBounds(const Eigen::AlignedBox3d& bounds, const Eigen::Vector3d& point)
{
  return !point.allFinite() || !bounds.contains(point);
}

bool catchIfOutside(const Eigen::AlignedBox3d& bounds, const btTransform& start, btRigidBody* rigid,
                    btDiscreteDynamicsWorld* world)
{
  if (!outsideBounds(bounds, toEigen(rigid->getCenterOfMassPosition())))
  {
    return false;
  }
  rigid->setCenterOfMassTransform(start);  // the world and interpolation transforms
  rigid->setLinearVelocity(btVector3(0, 0, 0));
  rigid->setAngularVelocity(btVector3(0, 0, 0));
  rigid->setInterpolationLinearVelocity(btVector3(0, 0, 0));
  rigid->setInterpolationAngularVelocity(btVector3(0, 0, 0));
  rigid->clearForces();
  world->updateSingleAabb(rigid);
  world->getBroadphase()->getOverlappingPairCache()->cleanProxyFromPairs(rigid->getBroadphaseHandle(),
                                                                         world->getDispatcher());
  return true;
}
}  // namespace god_finger::internal
