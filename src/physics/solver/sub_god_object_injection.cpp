#include "solver/sub_god_object_injection.h"

#include "bullet_helpers.h"
#include "god_finger/contact/sub_god_object_distance.h"

namespace god_finger::internal
{
void SubGodObjectInjector::inject(const AreaSolverInput& c, const Proxy& proxy, long step)
{
  const btCollisionObject* a = c.manifold->getBody0();
  const btCollisionObject* b = c.manifold->getBody1();
  const btManifoldPoint& contact = *c.contact;
  btPersistentManifold* target = nullptr;
  // Opposite points one after the other (0, n/2, 1, n/2 + 1, ...): the solver visits the points
  // in this order, and the ring's friction rows all act on one light proxy; visited around the
  // ring, each row's impulse pushed the proxy and the next row undid it, and 60 iterations left
  // a held twist creeping above 40 % of the pad's capacity (58-89 mrad in 3 s at 50 %); visited
  // in opposite pairs, the pushes cancel pairwise and it holds to 70 % (0.2 mrad).
  const int count = c.area->sub_god_object_count;
  for (int k = 0; k < count; ++k)
  {
    const int i = (k % 2 == 0) ? k / 2 : (count + 1) / 2 + k / 2;
    if (target == nullptr || target->getNumContacts() == MANIFOLD_CACHE_SIZE)
    {
      target = dispatcher_->getNewManifold(a, b);
      manifolds_.push_back(target);
    }
    // Same normal as the true contact; the object's point is the sub-god-object, the proxy's
    // point is offset along the normal by the distance.
    const double distance = tiltCorrectedDistance(contact.getDistance(), c.normal_world, c.object_to_pad,
                                                  c.area->positions[i] - c.point_world);
    const btVector3 fresh_on_object = toBullet(c.area->positions[i]);
    const btVector3 fresh_on_proxy = fresh_on_object + toBullet(c.normal_world) * distance;
    const btCollisionObject* proxy_object = c.proxy_is_a ? a : b;
    const btCollisionObject* object = c.proxy_is_a ? b : a;
    const btTransform pad_frame = padFrame(proxy, *proxy_object, c.normal_world);
    // The friction anchor: the pad's and the object's material points where this
    // sub-god-object began to stick, kept while it sticks; it starts again where the
    // sub-god-object is now when it is new, slipped in the last step (friction at its cone) or
    // lies away from where its anchor drifted (the area moved on).
    const int sgo_index = c.radial_index[i];
    const WarmStart& warm = proxy.warm_starts[c.body_index][sgo_index];
    btVector3 on_object = fresh_on_object;
    btVector3 on_proxy = fresh_on_proxy;
    if (warm.step == step - 1)
    {
      anchorIfSticking(warm, pad_frame, *object, c.area->radius, &on_object, &on_proxy);
    }
    const btVector3 on_a = c.proxy_is_a ? on_proxy : on_object;
    const btVector3 on_b = c.proxy_is_a ? on_object : on_proxy;
    btManifoldPoint point(a->getWorldTransform().invXform(on_a), b->getWorldTransform().invXform(on_b),
                          contact.m_normalWorldOnB, distance);
    point.m_positionWorldOnA = on_a;
    point.m_positionWorldOnB = on_b;
    point.m_combinedFriction = contact.m_combinedFriction;
    point.m_combinedRestitution = contact.m_combinedRestitution;
    point.m_combinedRollingFriction = contact.m_combinedRollingFriction;
    point.m_combinedSpinningFriction = contact.m_combinedSpinningFriction;
    // The pad's compliance (see FingerPadParams), as on the true contact, and the anchor: the
    // friction rows also correct the tangential drift between the anchored points.
    point.m_contactPointFlags =
        (contact.m_contactPointFlags & BT_CONTACT_FLAG_CONTACT_STIFFNESS_DAMPING) | BT_CONTACT_FLAG_FRICTION_ANCHOR;
    point.m_combinedContactStiffness1 = contact.m_combinedContactStiffness1;
    point.m_combinedContactDamping1 = contact.m_combinedContactDamping1;
    // Warm start from the same sub-god-object's impulses of the previous step, if it was
    // there. Bullet 3.24 warm-starts the normal row only (setFrictionConstraintImpulse zeroes
    // the friction rows' since 2019); the lateral impulses still tell the next step whether
    // this point slipped (anchorIfSticking).
    if (warm.step == step - 1)
    {
      point.m_appliedImpulse = warm.normal;
      point.m_appliedImpulseLateral1 = warm.lateral1;
      point.m_appliedImpulseLateral2 = warm.lateral2;
    }
    const int slot = target->addManifoldPoint(point);
    // The anchor as material points, in each body's frame at this step (before the solver moves
    // them): what the next step places back in the world.
    points_.push_back({target, slot, c.proxy_index, c.body_index, sgo_index, toEigen(pad_frame.invXform(on_proxy)),
                       toEigen(object->getWorldTransform().invXform(on_object))});
  }
}

void SubGodObjectInjector::recordImpulses(std::vector<Proxy>* proxies, long step)
{
  for (const InjectedPoint& record : points_)
  {
    const btManifoldPoint& point = record.manifold->getContactPoint(record.point);
    WarmStart& warm = (*proxies)[record.proxy].warm_starts[record.body][record.sub_god_object];
    warm.step = step;
    warm.normal = point.m_appliedImpulse;
    warm.lateral1 = point.m_appliedImpulseLateral1;
    warm.lateral2 = point.m_appliedImpulseLateral2;
    warm.friction = point.m_combinedFriction;
    warm.anchor_on_proxy = record.anchor_on_proxy;
    warm.anchor_on_object = record.anchor_on_object;
  }
}

void SubGodObjectInjector::release()
{
  points_.clear();
  for (btPersistentManifold* manifold : manifolds_)
  {
    dispatcher_->releaseManifold(manifold);
  }
  manifolds_.clear();
}
}  // namespace god_finger::internal
