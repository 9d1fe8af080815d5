// The finger pad as one constraint (pad_solver: constraint): a contact area's sub-god-objects
// reach the solver as one point instead of one point each. Internal to physics.
//
// The true contact becomes the pad: its solver point moves to the area's centre of pressure,
// and besides its normal row and two friction rows (with a friction anchor, as the
// sub-god-objects' have) it gets Bullet's torsional rows: one about the normal, bounded by
// mu x normal impulse x the area's torsional lever, and two about tangents (tilt), bounded by
// normal impulse x the area's support radius. Six rows per finger instead of 3 (1 + n_SGO).
//
// Bullet's torsional rows alone do not hold a load: they start from zero every step, carry no
// position error, and see the step's external torques one step late
// (btSequentialImpulseConstraintSolver::setupTorsionalFrictionConstraint), so a twisted object
// turns at the rate the torque gives it in one step. The solver (support_pass_solver.h) fixes
// this for the pad's rows: warm start from the last step, this step's external torque, and an
// orientation anchor (the object's turn relative to the pad since it began to stick, corrected
// at Bullet's friction ERP); a row that reaches its bound lets the anchor go (slip).
//
// Units: SI, world frame. Real-time safe: no allocation once the lists have grown.
#pragma once

#include "proxy.h"

#include "god_finger/physics/god_finger_world.h"

#include <btBulletDynamicsCommon.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace god_finger
{
// The pad's shape under uniform pressure over the area the sub-god-objects bound.
struct PadGeometry
{
  Eigen::Vector3d centre_of_pressure = Eigen::Vector3d::Zero();  // m, world, in the tangent plane at the contact
  double torsional_lever = 0.0;  // m: (1/A) integral of |r - cop| dA; (2/3) a for a disk of radius a
  double support_radius = 0.0;   // m: mean distance from the centre of pressure to the area's rim; a for a disk
};

// From the contact point `centre` (m, world), the normal and the area's kept sub-god-objects in
// walk order (a star-shaped polygon around `centre`). Fewer than 3 sub-god-objects: a point
// (levers zero, centre of pressure at `centre`).
PadGeometry padGeometry(const Eigen::Vector3d& centre, const Eigen::Vector3d& normal, const WorldContactArea& area);

// One pad in this step's solve: what the solver reads and writes for its torsional rows.
struct PadRows
{
  btManifoldPoint* point = nullptr;          // the pad's point (flagged kPadPointFlag, m_index0 = this row's index)
  const btCollisionObject* body0 = nullptr;  // the point's manifold's bodies
  const btCollisionObject* body1 = nullptr;
  PadState* state = nullptr;
  // Body B's turn relative to body A since the anchor (rad, world rotation vector).
  Eigen::Vector3d turn_since_anchor = Eigen::Vector3d::Zero();
  Eigen::Vector3d warm_torque_impulse = Eigen::Vector3d::Zero();  // N m s on B, world
};

// Marks a manifold point as a pad (Bullet uses the low 5 bits of m_contactPointFlags).
constexpr int kPadPointFlag = 1 << 12;
}  // namespace god_finger
