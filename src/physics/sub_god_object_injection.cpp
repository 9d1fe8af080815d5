#include "sub_god_object_injection.h"

#include "bullet_helpers.h"
#include "god_finger/core/sub_god_object_distance.h"

namespace god_finger
{
void SubGodObjectInjector::inject(const AreaContact& c, const Proxy& proxy, long step)
{
  const btCollisionObject* a = c.manifold->getBody0();
  const btCollisionObject* b = c.manifold->getBody1();
  const btManifoldPoint& contact = *c.contact;
  btPersistentManifold* target = nullptr;
  for (int i = 0; i < c.area->sub_god_object_count; ++i)
  {
    if (target == nullptr || target->getNumContacts() == MANIFOLD_CACHE_SIZE)
    {
      target = dispatcher_->getNewManifold(a, b);
      manifolds_.push_back(target);
    }
    // Same normal as the true contact; the object's point is the sub-god-object, the proxy's
    // point is offset along the normal by the distance.
    const double distance = tiltCorrectedDistance(contact.getDistance(), c.normal_world, c.object_to_pad,
                                                  c.area->positions[i] - c.point_world);
    const btVector3 on_object = toBullet(c.area->positions[i]);
    const btVector3 on_proxy = on_object + toBullet(c.normal_world) * distance;
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
    // The pad's compliance (see FingerPadParams), as on the true contact.
    point.m_contactPointFlags = contact.m_contactPointFlags & BT_CONTACT_FLAG_CONTACT_STIFFNESS_DAMPING;
    point.m_combinedContactStiffness1 = contact.m_combinedContactStiffness1;
    point.m_combinedContactDamping1 = contact.m_combinedContactDamping1;
    // Warm start from the same sub-god-object's impulses of the previous step, if it was
    // there (without it the solver's 30 iterations leave a slow creep, see README).
    const int sgo_index = c.radial_index[i];
    const WarmStart& warm = proxy.warm_starts[c.body_index][sgo_index];
    if (warm.step == step - 1)
    {
      point.m_appliedImpulse = warm.normal;
      point.m_appliedImpulseLateral1 = warm.lateral1;
      point.m_appliedImpulseLateral2 = warm.lateral2;
    }
    const int slot = target->addManifoldPoint(point);
    points_.push_back({target, slot, c.proxy_index, c.body_index, sgo_index});
  }
}

void SubGodObjectInjector::recordImpulses(std::vector<Proxy>* proxies, long step) const
{
  for (const InjectedPoint& record : points_)
  {
    const btManifoldPoint& point = record.manifold->getContactPoint(record.point);
    WarmStart& warm = (*proxies)[record.proxy].warm_starts[record.body][record.sub_god_object];
    warm.step = step;
    warm.normal = point.m_appliedImpulse;
    warm.lateral1 = point.m_appliedImpulseLateral1;
    warm.lateral2 = point.m_appliedImpulseLateral2;
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
}  // namespace god_finger
