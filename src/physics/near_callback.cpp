#include "near_callback.h"

#include "bullet_helpers.h"
#include "scene_body.h"

#include <algorithm>

namespace god_finger::internal
{
namespace
{
// A free body that collides through one convex shape, its own true surface: a ball, a box, a
// convex mesh (no FingerSurface of its own).
bool freeAndConvex(const btCollisionObject* object)
{
  return object->getUserIndex() == kKindBody && !object->isStaticOrKinematicObject() &&
         object->getUserPointer() == nullptr;
}

// The FingerSurface `self` offers `other` in this pair, or null for its collision shape: a
// finger, and a free convex body (a ball dropped into a cup), touch the true surface; a
// support (static) and a body that has a FingerSurface of its own touch the collision shape
// (two hollow bodies' true surfaces are two triangle meshes, which Bullet does not collide).
const FingerSurface* fingerSurfaceFor(const btCollisionObject* self, const btCollisionObject* other)
{
  if (self->getUserIndex() != kKindBody || (other->getUserIndex() != kKindProxy && !freeAndConvex(other)))
  {
    return nullptr;
  }
  return static_cast<const FingerSurface*>(self->getUserPointer());
}
}  // namespace

void worldNearCallback(btBroadphasePair& pair, btCollisionDispatcher& dispatcher, const btDispatcherInfo& info)
{
  const auto* a = static_cast<const btCollisionObject*>(pair.m_pProxy0->m_clientObject);
  const auto* b = static_cast<const btCollisionObject*>(pair.m_pProxy1->m_clientObject);
  if ((!a->isActive() && !b->isActive()) || (a->isStaticOrKinematicObject() && b->isStaticOrKinematicObject()))
  {
    return;
  }
  const FingerSurface* a_surface = fingerSurfaceFor(a, b);
  const FingerSurface* b_surface = fingerSurfaceFor(b, a);
  if (a_surface == nullptr && b_surface == nullptr)
  {
    btCollisionDispatcher::defaultNearCallback(pair, dispatcher, info);
    return;
  }
  if (!dispatcher.needsCollision(a, b))
  {
    return;
  }
  // As Bullet's default near callback, with the finger surface in place of the collision shape
  // (placed at the body's transform times its frame in the body). The algorithm Bullet keeps in
  // the pair is the one for these shapes: a pair always collides the same shapes.
  const btTransform a_transform =
      a_surface != nullptr ? a->getWorldTransform() * a_surface->in_body : a->getWorldTransform();
  const btTransform b_transform =
      b_surface != nullptr ? b->getWorldTransform() * b_surface->in_body : b->getWorldTransform();
  const btCollisionObjectWrapper a_wrap(nullptr, a_surface != nullptr ? a_surface->mesh->shape : a->getCollisionShape(),
                                        a, a_transform, -1, -1);
  const btCollisionObjectWrapper b_wrap(nullptr, b_surface != nullptr ? b_surface->mesh->shape : b->getCollisionShape(),
                                        b, b_transform, -1, -1);
  if (pair.m_algorithm == nullptr)
  {
    pair.m_algorithm = dispatcher.findAlgorithm(&a_wrap, &b_wrap, nullptr, BT_CONTACT_POINT_ALGORITHMS);
  }
  if (pair.m_algorithm == nullptr)
  {
    return;
  }
  btManifoldResult result(&a_wrap, &b_wrap);
  if (info.m_dispatchFunc == btDispatcherInfo::DISPATCH_DISCRETE)
  {
    pair.m_algorithm->processCollision(&a_wrap, &b_wrap, info, &result);
  }
  else
  {
    const btScalar time_of_impact = pair.m_algorithm->calculateTimeOfImpact(
        const_cast<btCollisionObject*>(a), const_cast<btCollisionObject*>(b), info, &result);
    if (info.m_timeOfImpact > time_of_impact)
    {
      const_cast<btDispatcherInfo&>(info).m_timeOfImpact = time_of_impact;
    }
  }
}

double deepestPenetrationAsCollided(btCollisionWorld* world, btCollisionObject* a, btCollisionObject* b)
{
  struct Deepest : btCollisionWorld::ContactResultCallback
  {
    double depth = 0.0;
    btScalar addSingleResult(btManifoldPoint& point, const btCollisionObjectWrapper*, int, int,
                             const btCollisionObjectWrapper*, int, int) override
    {
      depth = std::max(depth, -static_cast<double>(point.getDistance()));
      return 0;
    }
  };
  // A stand-in object of the surface at its place for a side that touches its FingerSurface.
  const auto stand_in = [](btCollisionObject* self, const FingerSurface* surface, btCollisionObject* object)
  {
    if (surface == nullptr)
    {
      return self;
    }
    object->setCollisionShape(surface->mesh->shape);
    object->setWorldTransform(self->getWorldTransform() * surface->in_body);
    return object;
  };
  btCollisionObject a_surface;
  btCollisionObject b_surface;
  btCollisionObject* first = stand_in(a, fingerSurfaceFor(a, b), &a_surface);
  btCollisionObject* second = stand_in(b, fingerSurfaceFor(b, a), &b_surface);
  Deepest deepest;
  world->contactPairTest(first, second, deepest);
  return deepest.depth;
}
}  // namespace god_finger::internal
