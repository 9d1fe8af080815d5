// The finger pad of one (proxy, body) pair: what it keeps from one step to the next. The one
// place of the pad's persistent state; this step's pads are pad_constraints.h's. Internal to
// physics.
//
// Two orientations of the object, for two different events (they are not one stored twice):
// - `object_at_contact` (both pad_solver layouts): the finger took its shape when the contact
//   began; the pad moves with the proxy and never rotates, so the object's turn since then
//   tilts the pad against the surface (contact/sub_god_object_distance.h). Frame: the object's
//   walk mesh (geometry) frame in the world. Kept while the contact lasts from step to step.
// - `object_at_twist_anchor` (pad_solver: constraint): the object's orientation when the pad
//   last began to stick; the pad's torsional rows pull the object back towards it
//   (pad_torsion.h). Frame: the object's centre of mass frame in the world. Let go when a
//   torsional row reached its bound (slip), or when the last step had no pad.
//
// Both are the object's orientations in the world. A 3-DOF finger's pad keeps the world's
// orientation (its proxy never turns). An oriented finger's pad (physics/oriented_finger.h)
// turns with the finger, as a finger pad does:
// - it sticks: the rows' anchor is the object where the finger's turn since
//   `finger_at_twist_anchor` carried it (all three axes: twist and tilt), and their target speed
//   is the finger's own angular velocity (pad_torsion.h), so a twisting or turning hand turns
//   what it holds;
// - it slips or rolls: a row at its bound (mu N lever about the normal, N a about a tangent)
//   lets the object lag, and the anchor is dragged along so that the object never lags more
//   than kPadStickAngle behind it (a 3-DOF pad lets its anchor go instead: a let-go anchor
//   restarts the row's torque from zero, a force step of 1.3e-3 N under roll_finger's rolling
//   pulp; dragged, the pulp rolls at a steady bounded torque: 2.4e-5 N);
// - its material points (friction anchors) are kept in padFrame (proxy.h): the finger's
//   orientation swung onto the surface, which turns with the finger's twist and with the normal
//   but not with its roll, so that the rolling pulp's area moves by R_f times the angle
//   (pulpContact's offset) instead of dragging the object;
// - it has no shape tilt (objectTurnSinceContact gives the identity: its pad lies on the surface).
// Tried and not kept (stop 36 and this one): the anchor following the finger's whole rotation
// and let go on a slip (roll_finger's force step 1.3e-3 N; the shape tilt then lost the points
// layout's contact for 63 steps); the twist alone, with the world's tilt rows (the cylinder turn
// is a tilt of each pad: 0.07 rad); no tilt rows at all, the round fingertip's rolling left to
// the moved area (the cylinder tumbled about the pinch line under a human-like hand, and at a
// 32 mm squeeze under a perfect one).
//
// Units: SI, world frame unless said. Real-time safe (no allocation).
#pragma once

#include "solver/warm_start.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace god_finger::internal
{
// rad: how far an oriented pad lets the object lag behind the finger's turn before it drags
// its anchor along (the pulp's own give; pad_state.h's header).
constexpr double kPadStickAngle = 0.02;

struct PadState
{
  // The pad's shape (both layouts).
  long contact_step = -2;  // the last step the contact existed
  Eigen::Matrix3d object_at_contact = Eigen::Matrix3d::Identity();

  // The pad as one constraint (pad_solver: constraint): its point's impulses and friction
  // anchor, as a sub-god-object's (linear.step: the last step it was solved), and its
  // orientation anchor.
  WarmStart linear;
  bool twist_slipped = true;
  Eigen::Quaterniond object_at_twist_anchor = Eigen::Quaterniond::Identity();
  // An oriented finger's proxy orientation when the anchor was set.
  Eigen::Quaterniond finger_at_twist_anchor = Eigen::Quaterniond::Identity();
  Eigen::Vector3d torque_impulse = Eigen::Vector3d::Zero();
  double object_side = 1.0;  // +1: the object is the manifold's body B (its torque impulse is torque_impulse), -1: A //
                             // N m s on the manifold's body B, world
};

// The contact of `pad` exists at step `step`, with the object's walk mesh at
// `object_to_world`: a new contact (none in the last step) takes the object's orientation now.
// Returns the object's rotation relative to the pad since the contact began (world): the
// identity for an oriented finger's pad (`oriented`), which lies on the surface.
inline Eigen::Matrix3d objectTurnSinceContact(const Eigen::Isometry3d& object_to_world, long step, bool oriented,
                                              PadState* pad)
{
  if (pad->contact_step != step - 1)
  {
    pad->object_at_contact = object_to_world.linear();
  }
  pad->contact_step = step;
  if (oriented)
  {
    return Eigen::Matrix3d::Identity();
  }
  return pad->object_at_contact * object_to_world.linear().transpose();
}
}  // namespace god_finger::internal
