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
// Both are the object's orientations in the world: the pad's reference is the world's, right for a
// 3-DOF finger (its proxy never rotates), and an oriented finger's too (its proxy's orientation,
// oriented_finger.h, is not used here): a 6-DOF finger turning with what it holds is resisted as a
// non-turning one (cylinder turn with oriented fingers, 20 mm: no turn). Open: which part of the
// finger's rotation the pad follows. All of it turns the cylinder (90 degrees at 20 mm) but drags
// the box under roll_finger's rolling pulp (force step 1.3e-3 N, 1.7e-5 before) and, in the
// distances, tilts the pad into it (points layout: contact lost for 63 steps); the pulp rolled
// onto the surface (its twist only) keeps roll_finger but turns the cylinder 0.07 rad.
//
// Units: SI, world frame unless said. Real-time safe (no allocation).
#pragma once

#include "solver/warm_start.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace god_finger::internal
{
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
  Eigen::Vector3d torque_impulse = Eigen::Vector3d::Zero();  // N m s on the manifold's body B, world
};

// The contact of `pad` exists at step `step`, with the object's walk mesh at
// `object_to_world`: a new contact (none in the last step) takes the object's orientation now.
// Returns the object's rotation relative to the pad since the contact began (world).
inline Eigen::Matrix3d objectTurnSinceContact(const Eigen::Isometry3d& object_to_world, long step, PadState* pad)
{
  if (pad->contact_step != step - 1)
  {
    pad->object_at_contact = object_to_world.linear();
  }
  pad->contact_step = step;
  return pad->object_at_contact * object_to_world.linear().transpose();
}
}  // namespace god_finger::internal
