// Bullet's sequential-impulse solver plus a support pass for proxies pressing light objects
// onto static ones. Internal to physics.
//
// Sequential impulses move about one object-mass of momentum per iteration through a stack
// proxy -> object -> static support, so an object much lighter than the proxy (20 g) sank into
// its support while pressed: 7 mm at 1/1000 of the proxy's mass after 60 iterations. After the
// regular iterations, `support_passes` passes (shock propagation, Guendelman et al. 2003,
// restricted to this stack) solve again, in order: each normal row between a dynamic object and
// a static body (the object stops moving into its support), then each normal row between a
// proxy and such a supported object with the object held fixed (the proxy stops moving into it;
// its push goes to the static support through the object, which it rests on). Friction rows
// and every other row are as Bullet solved them. Only objects lighter than the proxy are held
// (for heavier ones the iterations converge); one that touches nothing static (pinched in the
// air, lying on another dynamic object) is not.
//
// Torsional rows (Bullet's spinning and rolling friction): Bullet sets them up without the
// step's external torques, which they then meet one step late, and without an effective mass
// when neither body can turn (0/0). Here every such row sees this step's external torques and a
// row between two bodies that cannot turn is empty. The pads' rows (pad_constraint.h) are also
// warm-started and corrected towards their orientation anchor; their impulses and slips go back
// to the pads' states after the solve.
//
// Every torsional row is solved at its lever (scaleToLever): Bullet measures a row's residual in
// its own velocity, rad/s for these rows, so the iterations' tolerance (m/s) asked them for 10 um/s
// read as 10 urad/s, and they ran every iteration (god_finger 54 per step where god_object needs
// 26). Scaled by the row's coefficient L (m), a row's velocity is L times the angular one (m/s, the
// speed at the lever) and its impulse is the torque impulse over L, bounded by the normal impulse:
// the same solution, one tolerance for every row.
//
// Units: Bullet's (SI). Counts the contact points it receives (all, and the proxies').
// Not real-time safe to construct; solving reuses Bullet's pools.
#pragma once

#include "pad_constraint.h"

#include <btBulletDynamicsCommon.h>

#include <vector>

namespace god_finger
{
class SupportPassSolver : public btSequentialImpulseConstraintSolver
{
 public:
  explicit SupportPassSolver(int support_passes) : support_passes_(support_passes) {}

  btScalar solveGroup(btCollisionObject** bodies, int num_bodies, btPersistentManifold** manifolds, int num_manifolds,
                      btTypedConstraint** constraints, int num_constraints, const btContactSolverInfo& info,
                      btIDebugDraw* debug_draw, btDispatcher* dispatcher) override;
  void resetCounts()
  {
    points_ = 0;
    proxy_points_ = 0;
    rows_ = 0;
  }
  int points() const
  {
    return points_;
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
  // This step's pads (owned by the sub-god-object injector), or none.
  void setPadRows(std::vector<PadRows>* pads)
  {
    pads_ = pads;
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
  void supportPass();
  // Scales a torsional row (coefficient L > 0, m) so that its velocity is L times its angular
  // velocity (m/s) and its impulse the torque impulse over L (N s); its coefficient becomes 1.
  static void scaleToLever(btSolverConstraint* row);
  // The pad a torsional row belongs to, or null.
  PadRows* padOf(const btSolverConstraint& row);
  std::vector<PadRows>* pads_ = nullptr;
  int support_passes_;
  std::vector<char> supported_;
  int points_ = 0;
  int proxy_points_ = 0;
  int rows_ = 0;
};
}  // namespace god_finger
