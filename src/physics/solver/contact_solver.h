// The world's constraint solver: Bullet's sequential-impulse solver with three additions, each
// in its own file, and counts of what it solved. Internal to physics.
//
// - Torsional rows (torsional_rows.h): every spinning and rolling friction row sees this step's
//   external torques, is solved at its lever, and is dropped when neither body can turn.
// - Pad rows (pad_torsion.h): the torsional rows of this step's pads (pad_constraints.h) are
//   corrected towards their orientation anchor and warm-started; after the solve their impulses
//   and slips go back to the pads' states. A torsional row finds its pad through its normal row
//   (Bullet's m_frictionIndex) in a side table built per solve: normal row -> pad, by the row's
//   manifold point.
// - Support passes (support_pass.h): after the iterations, proxies pressing light objects onto
//   static ones are held.
//
// Units: Bullet's (SI). Counts the proxies' contact points it receives and the rows it solves.
// Not real-time safe to construct; solving reuses Bullet's pools and its own lists once they
// have grown.
#pragma once

#include "solver/pad_constraints.h"

#include <btBulletDynamicsCommon.h>

#include <vector>

namespace god_finger::internal
{
class ContactSolver : public btSequentialImpulseConstraintSolver
{
 public:
  // `pads`: this step's pads (owned by the world), or null; outlives the solver.
  ContactSolver(int support_passes, PadConstraints* pads) : pads_(pads), support_passes_(support_passes) {}

  btScalar solveGroup(btCollisionObject** bodies, int num_bodies, btPersistentManifold** manifolds, int num_manifolds,
                      btTypedConstraint** constraints, int num_constraints, const btContactSolverInfo& info,
                      btIDebugDraw* debug_draw, btDispatcher* dispatcher) override;
  void resetCounts()
  {
    proxy_points_ = 0;
    rows_ = 0;
  }
  int proxyPoints() const
  {
    return proxy_points_;
  }
  int rows() const
  {
    return rows_;
  }
  // Iterations the last solve ran (solver_iterations at most; fewer once within
  // solver_tolerance).
  int iterationsUsed() const
  {
    return m_analyticsData.m_numIterationsUsed;
  }

 protected:
  void convertContacts(btPersistentManifold** manifolds, int num_manifolds, const btContactSolverInfo& info) override;
  btScalar solveGroupCacheFriendlyFinish(btCollisionObject** bodies, int num_bodies,
                                         const btContactSolverInfo& info) override;
  btScalar solveGroupCacheFriendlyIterations(btCollisionObject** bodies, int num_bodies,
                                             btPersistentManifold** manifolds, int num_manifolds,
                                             btTypedConstraint** constraints, int num_constraints,
                                             const btContactSolverInfo& info, btIDebugDraw* debug_draw) override;

 private:
  // The pad a torsional row belongs to, or null.
  StepPad* padOf(const btSolverConstraint& row) const;
  PadConstraints* pads_;
  // This solve's side table: per normal row (Bullet's contact pool), its pad or null; empty
  // when there is no pad.
  std::vector<StepPad*> pad_of_contact_row_;
  int support_passes_;
  std::vector<char> supported_;
  int proxy_points_ = 0;
  int rows_ = 0;
};
}  // namespace god_finger::internal
