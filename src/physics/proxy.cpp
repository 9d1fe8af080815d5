#include "proxy.h"

#include "bullet_helpers.h"

namespace god_finger::internal
{
void buildProxyBody(const CouplingParams& coupling, const FingerPadParams& pad, int index, int body_count, Proxy* proxy)
{
  proxy->shape = std::make_unique<btSphereShape>(coupling.proxy_radius);
  // Zero inertia: Bullet's inverse inertia is then zero and the proxy never turns. Locking its
  // rotation with setAngularFactor(0) alone is not enough: Bullet's torsional and rolling
  // friction rows take their effective mass from the inverse inertia without the angular factor
  // (btSequentialImpulseConstraintSolver::setupTorsionalFrictionConstraint), so the 20 g
  // sphere's tiny inertia made every such row about 1e5 times too weak and soft_finger resisted
  // no twist at all.
  const btVector3 inertia(0, 0, 0);
  btRigidBody::btRigidBodyConstructionInfo info(coupling.proxy_mass, nullptr, proxy->shape.get(), inertia);
  info.m_startWorldTransform = btTransform(btQuaternion::getIdentity(), toBullet(proxy->initial));
  info.m_friction = 1.0;  // Bullet multiplies: the object's coefficient applies
  proxy->rigid = std::make_unique<btRigidBody>(info);
  proxy->rigid->setUserIndex(kKindProxy);
  proxy->rigid->setUserIndex2(index);
  proxy->rigid->setAngularFactor(0.0);
  proxy->rigid->setContactStiffnessAndDamping(pad.stiffness, pad.damping);
  proxy->rigid->setActivationState(DISABLE_DEACTIVATION);
  proxy->rigid->setFlags(proxy->rigid->getFlags() | BT_DISABLE_WORLD_GRAVITY);
  // Continuous collision so that a fast hand does not tunnel through thin objects.
  proxy->rigid->setCcdMotionThreshold(0.5 * coupling.proxy_radius);
  proxy->rigid->setCcdSweptSphereRadius(0.9 * coupling.proxy_radius);
  proxy->target = proxy->initial;
  proxy->previous_target = proxy->initial;
  proxy->state = InterfaceState();
  proxy->state.interface_position = proxy->initial;
  proxy->state.proxy_position = proxy->initial;
  proxy->orientation.restart();
  proxy->state.oriented = proxy->orientation.oriented;
  proxy->state.interface_orientation = proxy->orientation.target;
  proxy->state.proxy_orientation = proxy->orientation.proxy;
  proxy->reference_tangents.assign(body_count, Eigen::Vector3d::Zero());
  proxy->warm_starts.assign(body_count, {});
  proxy->pads.assign(body_count, PadState());
  proxy->let_go_steps = 0;
  proxy->soft_load.setZero();
  proxy->soft_load_body = -1;
}
void remapBodies(const std::vector<int>& old_of_new, Proxy* proxy)
{
  std::vector<Eigen::Vector3d> tangents(old_of_new.size(), Eigen::Vector3d::Zero());
  std::vector<std::array<WarmStart, ContactParams::kMaxSubGodObjects>> warm_starts(old_of_new.size());
  std::vector<PadState> pads(old_of_new.size());
  int soft_load_body = -1;
  for (std::size_t i = 0; i < old_of_new.size(); ++i)
  {
    const int old = old_of_new[i];
    if (old < 0)
    {
      continue;
    }
    tangents[i] = proxy->reference_tangents[old];
    warm_starts[i] = proxy->warm_starts[old];
    pads[i] = proxy->pads[old];
    soft_load_body = old == proxy->soft_load_body ? static_cast<int>(i) : soft_load_body;
  }
  proxy->reference_tangents = std::move(tangents);
  proxy->warm_starts = std::move(warm_starts);
  proxy->pads = std::move(pads);
  if (soft_load_body < 0)
  {
    proxy->soft_load.setZero();
  }
  proxy->soft_load_body = soft_load_body;
}

namespace
{
// Whether a contact test found any point (Bullet's contact threshold included).
struct TouchesAnything : btCollisionWorld::ContactResultCallback
{
  btScalar addSingleResult(btManifoldPoint&, const btCollisionObjectWrapper*, int, int, const btCollisionObjectWrapper*,
                           int, int) override
  {
    any = true;
    return 0.0;
  }
  bool any = false;
};

// The closest hit of a sweep, the swept proxy's own body left out.
struct SweepFrom : btCollisionWorld::ClosestConvexResultCallback
{
  SweepFrom(const btCollisionObject* self, const btVector3& from, const btVector3& to)
      : ClosestConvexResultCallback(from, to), self(self)
  {
  }
  bool needsCollision(btBroadphaseProxy* other) const override
  {
    return other->m_clientObject != self && ClosestConvexResultCallback::needsCollision(other);
  }
  const btCollisionObject* self;
};
}  // namespace

bool carriable(const Proxy& proxy, const Eigen::Vector3d& by)
{
  return proxy.state.contact_count == 0 && proxy.let_go_steps == 0 && by.allFinite() && !by.isZero(0.0);
}

bool carryFreeProxy(btCollisionWorld* world, const Eigen::Vector3d& by, Proxy* proxy)
{
  if (!carriable(*proxy, by))
  {
    return false;
  }
  btRigidBody& body = *proxy->rigid;
  TouchesAnything touches;
  world->contactTest(&body, touches);
  if (touches.any)
  {
    return false;  // in or at a body's shape where it is: left to the dynamics and the near callback
  }
  const btTransform from = body.getWorldTransform();
  btTransform to = from;
  to.setOrigin(from.getOrigin() + btVector3(by.x(), by.y(), by.z()));
  SweepFrom sweep(&body, from.getOrigin(), to.getOrigin());
  const btBroadphaseProxy* handle = body.getBroadphaseHandle();
  if (handle != nullptr)
  {
    sweep.m_collisionFilterGroup = handle->m_collisionFilterGroup;
    sweep.m_collisionFilterMask = handle->m_collisionFilterMask;
  }
  world->convexSweepTest(proxy->shape.get(), from, to, sweep);
  if (sweep.hasHit())
  {
    return false;  // something on the way: the coupling pulls it there as usual
  }
  body.setWorldTransform(to);
  body.setInterpolationWorldTransform(to);
  return true;
}
}  // namespace god_finger::internal
