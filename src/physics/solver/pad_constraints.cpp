#include "solver/pad_constraints.h"

#include "bullet_helpers.h"
#include "god_finger/contact/sub_god_object_distance.h"
#include "solver/pad_geometry.h"

namespace god_finger::internal
{
namespace
{
Eigen::Quaterniond padOrientation(const btTransform& frame)
{
  const btQuaternion q = frame.getRotation();
  return Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z());
}

Eigen::Quaterniond orientationOf(const btCollisionObject& object)
{
  return padOrientation(object.getWorldTransform());
}
}  // namespace

void PadConstraints::add(const AreaSolverInput& c, Proxy* proxy, long step)
{
  btManifoldPoint& contact = *c.contact;
  const btCollisionObject* a = c.manifold->getBody0();
  const btCollisionObject* b = c.manifold->getBody1();
  const btCollisionObject* proxy_object = c.proxy_is_a ? a : b;
  const btCollisionObject* object = c.proxy_is_a ? b : a;
  PadState& state = proxy->pads[c.body_index];
  const bool continued = state.linear.step == step - 1;
  const PadGeometry pad = padGeometry(c.point_world, c.normal_world, *c.area);
  const btTransform pad_frame = padFrame(*proxy, *proxy_object, c.normal_world);
  // The solver point at the centre of pressure, at its tilt-corrected distance, anchored as a
  // sub-god-object is.
  const double distance = tiltCorrectedDistance(contact.getDistance(), c.normal_world, c.object_to_pad,
                                                pad.centre_of_pressure - c.point_world);
  btVector3 on_object = toBullet(pad.centre_of_pressure);
  btVector3 on_proxy = on_object + toBullet(c.normal_world) * distance;
  if (continued)
  {
    anchorIfSticking(state.linear, pad_frame, *object, c.area->radius, &on_object, &on_proxy);
  }
  contact.m_positionWorldOnA = c.proxy_is_a ? on_proxy : on_object;
  contact.m_positionWorldOnB = c.proxy_is_a ? on_object : on_proxy;
  contact.m_distance1 = distance;
  contact.m_contactPointFlags |= BT_CONTACT_FLAG_FRICTION_ANCHOR;
  // The whole pad's compliance on one point: the points layout's true contact and
  // sub-god-objects in parallel (FingerPadParams is per point), so that both layouts sink alike.
  if (contact.m_contactPointFlags & BT_CONTACT_FLAG_CONTACT_STIFFNESS_DAMPING)
  {
    const double points = 1.0 + c.area->sub_god_object_count;
    contact.m_combinedContactStiffness1 = points * btManifoldResult::calculateCombinedContactStiffness(a, b);
    contact.m_combinedContactDamping1 = points * btManifoldResult::calculateCombinedContactDamping(a, b);
  }
  contact.m_combinedSpinningFriction = contact.m_combinedFriction * pad.torsional_lever;
  // Bullet adds the torsional rows only when this is > 0: a point-like area (fewer than three
  // sub-god-objects, or on a static object, which the non-turning proxy cannot twist) has none.
  const bool turns = !object->isStaticOrKinematicObject() && pad.support_radius > 0.0;
  contact.m_combinedRollingFriction = turns ? pad.support_radius : 0.0;
  if (continued)
  {
    contact.m_appliedImpulse = state.linear.normal;
    contact.m_appliedImpulseLateral1 = state.linear.lateral1;
    contact.m_appliedImpulseLateral2 = state.linear.lateral2;
  }
  // The orientation anchor, and the object's turn since (as body B's turn relative to A).
  const Eigen::Quaterniond now = orientationOf(*object);
  const FingerOrientation& finger = proxy->orientation;
  // A 3-DOF pad lets its anchor go when a row slipped; an oriented one drags it (below).
  if (!continued || (state.twist_slipped && !finger.oriented))
  {
    state.object_at_twist_anchor = now;
    state.finger_at_twist_anchor = finger.proxy;
    state.torque_impulse.setZero();
  }
  const double sign = c.proxy_is_a ? 1.0 : -1.0;  // B relative to A
  state.object_side = sign;
  StepPad rows;
  rows.point = &contact;
  rows.body0 = a;
  rows.body1 = b;
  rows.state = &state;
  if (finger.oriented)
  {
    // Where the finger's turn since the anchor carried the object, and the object's turn from
    // there; beyond kPadStickAngle the anchor is dragged along (pad_state.h).
    const Eigen::Quaterniond carried =
        finger.proxy * state.finger_at_twist_anchor.conjugate() * state.object_at_twist_anchor;
    Eigen::AngleAxisd turn(now * carried.conjugate());
    if (turn.angle() > kPadStickAngle)
    {
      turn.angle() = kPadStickAngle;
      state.object_at_twist_anchor =
          state.finger_at_twist_anchor * finger.proxy.conjugate() * Eigen::Quaterniond(turn).conjugate() * now;
    }
    rows.turn_since_anchor = sign * turn.angle() * turn.axis();
    rows.follow_velocity = sign * finger.angular_velocity;
  }
  else
  {
    const Eigen::AngleAxisd turn(now * state.object_at_twist_anchor.conjugate());
    rows.turn_since_anchor = sign * turn.angle() * turn.axis();
  }
  rows.warm_torque_impulse = state.torque_impulse;
  state.twist_slipped = false;
  state.torque_impulse.setZero();
  pads_.push_back(rows);
  // The anchor as material points, as for a sub-god-object.
  state.linear.anchor_on_proxy = toEigen(pad_frame.invXform(on_proxy));
  state.linear.anchor_on_object = toEigen(object->getWorldTransform().invXform(on_object));
}

StepPad* PadConstraints::find(const void* point)
{
  for (StepPad& pad : pads_)
  {
    if (pad.point == point)
    {
      return &pad;
    }
  }
  return nullptr;
}

void PadConstraints::recordImpulses(long step)
{
  // The point stays in Bullet's manifold: back to a plain contact, so that a step without a
  // contact area (or another model) does not find it a pad.
  for (StepPad& rows : pads_)
  {
    btManifoldPoint& point = *rows.point;
    WarmStart& warm = rows.state->linear;
    warm.step = step;
    warm.normal = point.m_appliedImpulse;
    warm.lateral1 = point.m_appliedImpulseLateral1;
    warm.lateral2 = point.m_appliedImpulseLateral2;
    warm.friction = point.m_combinedFriction;
    point.m_contactPointFlags &= ~BT_CONTACT_FLAG_FRICTION_ANCHOR;
    point.m_combinedSpinningFriction = btManifoldResult::calculateCombinedSpinningFriction(rows.body0, rows.body1);
    point.m_combinedRollingFriction = btManifoldResult::calculateCombinedRollingFriction(rows.body0, rows.body1);
    if (point.m_contactPointFlags & BT_CONTACT_FLAG_CONTACT_STIFFNESS_DAMPING)
    {
      point.m_combinedContactStiffness1 = btManifoldResult::calculateCombinedContactStiffness(rows.body0, rows.body1);
      point.m_combinedContactDamping1 = btManifoldResult::calculateCombinedContactDamping(rows.body0, rows.body1);
    }
  }
  pads_.clear();
}
}  // namespace god_finger::internal
