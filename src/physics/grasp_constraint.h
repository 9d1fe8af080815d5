// The grasp constraint (WorldParams::grasp_constraint: aggregate): the twist rows of two or more
// finger pads on one dynamic body, whose normals are (anti)parallel (a pinch), solved as one row
// about the grasp axis. Internal to physics; the solver (contact_solver.h) runs it.
//
// Each pad's twist row (pad_torsion.h) holds a torque about its normal up to its own bound,
// mu N_i L_i (N_i its contact's normal impulse, L_i the area's torsional lever). Here those rows
// leave Bullet's pool and become one row on the body: its torque impulse T about the grasp axis g
// (the first pad's normal, on the body's side) is bounded by the sum of the pads' bounds,
// |T| <= sum_i mu N_i L_i, recomputed from the normal rows at every iteration as Bullet does
// for each pad. That is no more than the pads transmit in reality (each pad's share of T is in
// proportion to its bound, so within it), and with no normal impulse nothing holds: an opened
// grip lets its body fall freely. The row's target is the pads' targets (this step's external
// torque, each pad's orientation anchor at the friction ERP) averaged by lever; its warm start
// the pads' warm starts. After the solve, T goes back to the pads' states in those shares, and
// the grasp slips (every pad lets its anchor go) only when T reached the summed bound: one pad
// whose normal force dips no longer lets its anchor go while the others hold.
// Pads whose normals are not parallel to g (within 2.6 degrees) and single pads keep their own
// rows, as do every pad's tilt rows; linear friction rows are Bullet's.
//
// Measured (bench/operator_bench.cpp, layout god_finger/aggregate against god_finger; 20
// operators): no steadier. The same twist limit (9.913 mm, the perfect hand), and the same share
// of operators keeping the turn within 0.05 rad at every squeeze: 0/20 at 10, 12 mm, 1/20 at 13,
// 3/20 at 14, 9/20 at 15, 13/20 at the target 15.86 and at 16, 20/20 at 20 mm; the turns differ
// by a few per cent per run. As it must: about the pinch normal the pads' tangential frictions
// have no lever (both contacts lie on the axis, but for a millimetre of misalignment, which the
// linear friction rows already hold), so the grasp's torque is only the pads' torsion, and the
// sum of their bounds is what the independent rows reach once converged. Hence off by default.
//
// Assumes the proxies do not turn (zero inverse inertia, proxy.cpp): a twist row's velocity is
// the body's angular velocity about its axis.
// Units: Bullet's (SI, world frame); T in N m s. Real-time safe once its lists have grown.
#pragma once

#include "pad_constraints.h"

#include <btBulletDynamicsCommon.h>

#include <vector>

namespace god_finger
{
class GraspConstraints
{
 public:
  // After the pads' torsional rows were prepared (scaled, external torques, anchored and warm
  // started; contact_solver.cpp): takes the twist rows of pads on a shared body out of
  // `torsional` into grasps. `pad_of_contact_row` maps a normal row (`contacts`) to its pad.
  void collect(const std::vector<StepPad*>& pad_of_contact_row,
               const btAlignedObjectArray<btSolverConstraint>& contacts, btAlignedObjectArray<btSolverBody>& bodies,
               btAlignedObjectArray<btSolverConstraint>* torsional);
  // One iteration over the grasps, after Bullet's rows; returns the largest velocity correction
  // squared ((m/s)^2 at the mean lever), as Bullet's iterations do.
  btScalar iterate(const btAlignedObjectArray<btSolverConstraint>& contacts,
                   btAlignedObjectArray<btSolverBody>& bodies);
  // After the iterations and support passes: each grasp within the bound of the final normal
  // impulses, its impulse into its pads' states, slips marked. Forgets the grasps.
  void finish(const btAlignedObjectArray<btSolverConstraint>& contacts, btAlignedObjectArray<btSolverBody>& bodies);
  int count() const
  {
    return static_cast<int>(grasps_.size());
  }

 private:
  struct Member
  {
    StepPad* pad = nullptr;
    int contact_row = -1;    // its normal row in Bullet's contact pool
    btScalar lever = 0.0;    // signed: the row's axis on the body . g (m, mu L)
    bool body_is_b = false;  // the body is the manifold's body B
  };
  struct Grasp
  {
    int body = -1;                     // solver body
    btVector3 axis;                    // g, unit, world
    btVector3 angular_component;       // I^-1 g (rad/s per N m s)
    btScalar inverse_effective = 0.0;  // g . I^-1 g
    btScalar target = 0.0;             // rad/s about g: the velocity change the row asks for
    btScalar impulse = 0.0;            // T, N m s about g on the body
    btScalar mean_lever = 0.0;         // m, for the residual
    int first = 0;                     // its members in members_
    int count = 0;
  };
  btScalar bound(const Grasp& grasp, const btAlignedObjectArray<btSolverConstraint>& contacts) const;
  void apply(Grasp* grasp, btScalar impulse, btAlignedObjectArray<btSolverBody>& bodies);
  std::vector<Grasp> grasps_;
  std::vector<Member> members_;
  // Scratch: the pads' twist rows (indices in the torsional pool), whether grouped yet, and the
  // rows that leave the pool.
  std::vector<int> candidates_;
  std::vector<char> grouped_;
  std::vector<int> removed_;
};
}  // namespace god_finger
