// The finger pad as one constraint (pad_solver: constraint): a contact area's sub-god-objects
// reach the solver as one point instead of one point each. This step's pads; what a pad keeps
// between steps is its PadState (pad_state.h). Internal to physics.
//
// The true contact becomes the pad: its solver point moves to the area's centre of pressure
// (pad_geometry.h), and besides its normal row and two friction rows (with a friction anchor,
// as the sub-god-objects' have, warm_start.h) it gets Bullet's torsional rows: one about the
// normal, bounded by mu x normal impulse x the area's torsional lever, and two about tangents
// (tilt), bounded by normal impulse x the area's support radius. Six rows per finger instead
// of 3 (1 + n_SGO).
//
// Bullet's torsional rows alone do not hold a load: they start from zero every step, carry no
// position error, and see the step's external torques one step late
// (btSequentialImpulseConstraintSolver::setupTorsionalFrictionConstraint), so a twisted object
// turns at the rate the torque gives it in one step. The solver (contact_solver.h) fixes this
// for the pad's rows (pad_torsion.h): warm start from the last step, this step's external
// torque (torsional_rows.h), and an orientation anchor (the object's turn relative to the pad
// since it began to stick, corrected at Bullet's friction ERP); a row that reaches its bound
// lets the anchor go (slip).
//
// Lifetime: pads are added between collision detection and the solver, found by the solver by
// their manifold point, and recorded after it (their points back to plain contacts); clear()
// before the next collision detection. Units: SI, world frame. Real-time safe: no allocation
// once the list has grown.
#pragma once

#include "area_solver_input.h"
#include "proxy.h"
#include "solver/pad_state.h"

#include <btBulletDynamicsCommon.h>

#include <Eigen/Core>
#include <vector>

namespace god_finger::internal
{
// One pad in this step's solve: what the solver reads and writes for its torsional rows.
struct StepPad
{
  btManifoldPoint* point = nullptr;          // the pad's point (the true contact, in Bullet's manifold)
  const btCollisionObject* body0 = nullptr;  // the point's manifold's bodies
  const btCollisionObject* body1 = nullptr;
  PadState* state = nullptr;
  // Body B's turn relative to body A since the orientation anchor (rad, world rotation vector);
  // an oriented finger's: relative to where the finger's turn carried it (pad_state.h).
  Eigen::Vector3d turn_since_anchor = Eigen::Vector3d::Zero();
  // The rows' target speed of B relative to A (rad/s, world): an oriented finger's angular
  // velocity (its pad turns with it), zero for a 3-DOF finger.
  Eigen::Vector3d follow_velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d warm_torque_impulse = Eigen::Vector3d::Zero();  // N m s on B, world
};

class PadConstraints
{
 public:
  // Makes the true contact of `contact` the pad of step `step`, warm-started and anchored from
  // `proxy`'s pad state of step `step - 1`.
  void add(const AreaSolverInput& contact, Proxy* proxy, long step);
  // This step's pad whose point is `point`, or null.
  StepPad* find(const void* point);
  bool empty() const
  {
    return pads_.empty();
  }
  // After the solver of step `step`: each pad's impulses into its state (the solver wrote the
  // torsional impulses and slips, pad_torsion.h); its point back to a plain contact.
  void recordImpulses(long step);
  // Forgets this step's pads (their points stay in Bullet's manifolds as they are).
  void clear()
  {
    pads_.clear();
  }

 private:
  std::vector<StepPad> pads_;
};
}  // namespace god_finger::internal
