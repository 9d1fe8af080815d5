#include "support_pass_solver.h"

#include "bullet_helpers.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace god_finger
{
namespace
{
bool isProxy(const btSolverBody& body)
{
  return body.m_originalBody != nullptr && body.m_originalBody->getUserIndex() == kKindProxy;
}

bool isStatic(const btSolverBody& body)
{
  return body.m_originalBody == nullptr || body.m_originalBody->getInvMass() == 0.0;
}

bool isDynamicObject(const btSolverBody& body)
{
  return !isStatic(body) && !isProxy(body);
}

// A torsional row's bound for its contact's normal impulse, as Bullet's iterations set it
// (btSequentialImpulseConstraintSolver::solveSingleIteration: coefficient x normal impulse,
// capped at the coefficient; zero while the contact does not push).
btScalar torsionalBound(const btSolverConstraint& row, const btSolverConstraint& contact)
{
  const btScalar normal = contact.m_appliedImpulse;
  return normal > 0.0 ? std::min(row.m_friction * normal, row.m_friction) : btScalar(0.0);
}
}  // namespace

void SupportPassSolver::scaleToLever(btSolverConstraint* row)
{
  // Lever L = the row's coefficient (m): torque = L x an impulse bounded by the normal impulse.
  const btScalar lever = row->m_friction;
  if (!(lever > 0.0))
  {
    return;
  }
  row->m_relpos1CrossNormal *= lever;
  row->m_relpos2CrossNormal *= lever;
  row->m_angularComponentA *= lever;
  row->m_angularComponentB *= lever;
  row->m_jacDiagABInv /= lever * lever;
  row->m_rhs /= lever;
  row->m_appliedImpulse /= lever;
  row->m_friction = 1.0;
}

btScalar SupportPassSolver::solveGroup(btCollisionObject** bodies, int num_bodies, btPersistentManifold** manifolds,
                                       int num_manifolds, btTypedConstraint** constraints, int num_constraints,
                                       const btContactSolverInfo& info, btIDebugDraw* debug_draw,
                                       btDispatcher* dispatcher)
{
  for (int i = 0; i < num_manifolds; ++i)
  {
    points_ += manifolds[i]->getNumContacts();
    if (manifolds[i]->getBody0()->getUserIndex() == kKindProxy ||
        manifolds[i]->getBody1()->getUserIndex() == kKindProxy)
    {
      proxy_points_ += manifolds[i]->getNumContacts();
    }
  }
  return btSequentialImpulseConstraintSolver::solveGroup(bodies, num_bodies, manifolds, num_manifolds, constraints,
                                                         num_constraints, info, debug_draw, dispatcher);
}

PadRows* SupportPassSolver::padOf(const btSolverConstraint& row)
{
  const btManifoldPoint* point =
      static_cast<const btManifoldPoint*>(m_tmpSolverContactConstraintPool[row.m_frictionIndex].m_originalContactPoint);
  if (pads_ == nullptr || point == nullptr || (point->m_contactPointFlags & kPadPointFlag) == 0)
  {
    return nullptr;
  }
  const int index = point->m_index0;
  if (index < 0 || index >= static_cast<int>(pads_->size()) || (*pads_)[index].point != point)
  {
    return nullptr;
  }
  return &(*pads_)[index];
}

void SupportPassSolver::convertContacts(btPersistentManifold** manifolds, int num_manifolds,
                                        const btContactSolverInfo& info)
{
  btSequentialImpulseConstraintSolver::convertContacts(manifolds, num_manifolds, info);
  btAlignedObjectArray<btSolverConstraint>& torsional = m_tmpSolverContactRollingFrictionConstraintPool;
  for (int j = 0; j < torsional.size(); ++j)
  {
    if (!std::isfinite(torsional[j].m_jacDiagABInv))
    {
      // Neither body can turn (a proxy on a static object): no row. (Kept with a zero
      // effective mass, Bullet's row solve would return 0 / 0 as its residual and the
      // iterations would never stop early.) Nothing indexes this pool.
      torsional.swap(j, torsional.size() - 1);
      torsional.pop_back();
      --j;
    }
  }
  rows_ += m_tmpSolverContactConstraintPool.size() + m_tmpSolverContactFrictionConstraintPool.size() + torsional.size();
  for (int j = 0; j < torsional.size(); ++j)
  {
    btSolverConstraint& row = torsional[j];
    scaleToLever(&row);
    const btSolverBody& a = m_tmpSolverBodyPool[row.m_solverBodyIdA];
    const btSolverBody& b = m_tmpSolverBodyPool[row.m_solverBodyIdB];
    // This step's external torques, which Bullet leaves out of these rows' velocity.
    const btScalar external = (a.m_originalBody ? row.m_relpos1CrossNormal.dot(a.m_externalTorqueImpulse) : 0.0) +
                              (b.m_originalBody ? row.m_relpos2CrossNormal.dot(b.m_externalTorqueImpulse) : 0.0);
    row.m_rhs -= external * row.m_jacDiagABInv;
    const PadRows* pad = padOf(row);
    if (pad == nullptr)
    {
      continue;
    }
    // The row turns B relative to A about `axis`; towards the anchor at the friction ERP.
    const btVector3& axis = row.m_relpos2CrossNormal;
    const double turned = toBullet(pad->turn_since_anchor).dot(axis);
    row.m_rhs -= turned * info.m_frictionERP / info.m_timeStep * row.m_jacDiagABInv;
    // Warm start inside this step's bound (from the normal row's warm impulse, as the
    // iterations will bound it).
    if (info.m_solverMode & SOLVER_USE_WARMSTARTING)
    {
      const btScalar bound = torsionalBound(row, m_tmpSolverContactConstraintPool[row.m_frictionIndex]);
      // The torque impulse about the scaled axis (L u), in the row's units (impulse at the lever L).
      const btScalar warm = btClamped<btScalar>(
          toBullet(pad->warm_torque_impulse).dot(axis) / axis.length2() * info.m_warmstartingFactor, -bound, bound);
      row.m_appliedImpulse = warm;
      btSolverBody& body_a = m_tmpSolverBodyPool[row.m_solverBodyIdA];
      btSolverBody& body_b = m_tmpSolverBodyPool[row.m_solverBodyIdB];
      body_a.internalApplyImpulse(row.m_contactNormal1 * body_a.internalGetInvMass(), row.m_angularComponentA, warm);
      body_b.internalApplyImpulse(row.m_contactNormal2 * body_b.internalGetInvMass(), row.m_angularComponentB, warm);
    }
  }
}

btScalar SupportPassSolver::solveGroupCacheFriendlyFinish(btCollisionObject** bodies, int num_bodies,
                                                          const btContactSolverInfo& info)
{
  for (int j = 0; j < m_tmpSolverContactRollingFrictionConstraintPool.size(); ++j)
  {
    btSolverConstraint& row = m_tmpSolverContactRollingFrictionConstraintPool[j];
    PadRows* pad = padOf(row);
    if (pad == nullptr)
    {
      continue;
    }
    // Within the bound of the final normal impulse (after the support passes): Bullet solves a
    // torsional row only while its contact pushes, so a warm-started impulse would otherwise
    // stay on a contact that let go.
    const btScalar bound = torsionalBound(row, m_tmpSolverContactConstraintPool[row.m_frictionIndex]);
    const btScalar clamped = btClamped<btScalar>(row.m_appliedImpulse, -bound, bound);
    if (clamped != row.m_appliedImpulse)
    {
      const btScalar change = clamped - row.m_appliedImpulse;
      btSolverBody& body_a = m_tmpSolverBodyPool[row.m_solverBodyIdA];
      btSolverBody& body_b = m_tmpSolverBodyPool[row.m_solverBodyIdB];
      body_a.internalApplyImpulse(row.m_contactNormal1 * body_a.internalGetInvMass(), row.m_angularComponentA, change);
      body_b.internalApplyImpulse(row.m_contactNormal2 * body_b.internalGetInvMass(), row.m_angularComponentB, change);
      row.m_appliedImpulse = clamped;
    }
    pad->state->torque_impulse += toEigen(row.m_relpos2CrossNormal) * row.m_appliedImpulse;
    // At its bound: the pad slipped about this axis (or let go).
    if (!(bound > 0.0) || std::abs(row.m_appliedImpulse) >= 0.999 * bound)
    {
      pad->state->twist_slipped = true;
    }
  }
  return btSequentialImpulseConstraintSolver::solveGroupCacheFriendlyFinish(bodies, num_bodies, info);
}

btScalar SupportPassSolver::solveGroupCacheFriendlyIterations(btCollisionObject** bodies, int num_bodies,
                                                              btPersistentManifold** manifolds, int num_manifolds,
                                                              btTypedConstraint** constraints, int num_constraints,
                                                              const btContactSolverInfo& info, btIDebugDraw* debug_draw)
{
  const btScalar residual = btSequentialImpulseConstraintSolver::solveGroupCacheFriendlyIterations(
      bodies, num_bodies, manifolds, num_manifolds, constraints, num_constraints, info, debug_draw);
  for (int pass = 0; pass < support_passes_; ++pass)
  {
    supportPass();
  }
  return residual;
}

void SupportPassSolver::supportPass()
{
  const int row_count = m_tmpSolverContactConstraintPool.size();
  const int body_count = m_tmpSolverBodyPool.size();
  // Per solver body: 1 rests on something static, 2 also pressed by a heavier proxy (held).
  // The buffer grows once.
  std::vector<char>& state = supported_;
  state.assign(body_count, 0);
  for (int r = 0; r < row_count; ++r)
  {
    const btSolverConstraint& row = m_tmpSolverContactConstraintPool[r];
    const btSolverBody& a = m_tmpSolverBodyPool[row.m_solverBodyIdA];
    const btSolverBody& b = m_tmpSolverBodyPool[row.m_solverBodyIdB];
    if (isDynamicObject(a) && isStatic(b))
    {
      state[row.m_solverBodyIdA] = 1;
    }
    else if (isStatic(a) && isDynamicObject(b))
    {
      state[row.m_solverBodyIdB] = 1;
    }
  }
  for (int r = 0; r < row_count; ++r)
  {
    const btSolverConstraint& row = m_tmpSolverContactConstraintPool[r];
    const btSolverBody& a = m_tmpSolverBodyPool[row.m_solverBodyIdA];
    const btSolverBody& b = m_tmpSolverBodyPool[row.m_solverBodyIdB];
    // Only objects lighter than the proxy: for heavier ones the iterations converge.
    if (isProxy(a) && isDynamicObject(b) && state[row.m_solverBodyIdB] != 0 &&
        b.m_originalBody->getInvMass() > a.m_originalBody->getInvMass())
    {
      state[row.m_solverBodyIdB] = 2;
    }
    else if (isProxy(b) && isDynamicObject(a) && state[row.m_solverBodyIdA] != 0 &&
             a.m_originalBody->getInvMass() > b.m_originalBody->getInvMass())
    {
      state[row.m_solverBodyIdA] = 2;
    }
  }
  // A held object stops moving into its support.
  for (int r = 0; r < row_count; ++r)
  {
    btSolverConstraint& row = m_tmpSolverContactConstraintPool[r];
    btSolverBody& a = m_tmpSolverBodyPool[row.m_solverBodyIdA];
    btSolverBody& b = m_tmpSolverBodyPool[row.m_solverBodyIdB];
    if ((state[row.m_solverBodyIdA] == 2 && isStatic(b)) || (isStatic(a) && state[row.m_solverBodyIdB] == 2))
    {
      m_resolveSingleConstraintRowLowerLimit(a, b, row);
    }
  }
  // A proxy stops moving into a held object.
  for (int r = 0; r < row_count; ++r)
  {
    btSolverConstraint& row = m_tmpSolverContactConstraintPool[r];
    btSolverBody& a = m_tmpSolverBodyPool[row.m_solverBodyIdA];
    btSolverBody& b = m_tmpSolverBodyPool[row.m_solverBodyIdB];
    const bool proxy_is_a = isProxy(a) && state[row.m_solverBodyIdB] == 2;
    const bool proxy_is_b = isProxy(b) && state[row.m_solverBodyIdA] == 2;
    if (!proxy_is_a && !proxy_is_b)
    {
      continue;
    }
    // The row with the object held fixed: only the proxy's inverse mass (it does not rotate)
    // and the row's compliance remain in its effective mass; the target velocity and the
    // compliance are the row's own (Bullet stores both scaled by the full effective mass).
    btSolverBody& proxy = proxy_is_a ? a : b;
    const btVector3& normal = proxy_is_a ? row.m_contactNormal1 : row.m_contactNormal2;
    const btScalar full = row.m_jacDiagABInv;
    if (!(full > 0))
    {
      continue;
    }
    const btScalar target_velocity = row.m_rhs / full;
    const btScalar compliance = row.m_cfm / full;
    const btScalar proxy_term = normal.dot(normal * proxy.internalGetInvMass());
    if (!(proxy_term + compliance > 0))
    {
      continue;
    }
    const btScalar held = 1 / (proxy_term + compliance);
    const btScalar velocity_a = row.m_contactNormal1.dot(a.internalGetDeltaLinearVelocity()) +
                                row.m_relpos1CrossNormal.dot(a.internalGetDeltaAngularVelocity());
    const btScalar velocity_b = row.m_contactNormal2.dot(b.internalGetDeltaLinearVelocity()) +
                                row.m_relpos2CrossNormal.dot(b.internalGetDeltaAngularVelocity());
    btScalar delta = held * (target_velocity - velocity_a - velocity_b - btScalar(row.m_appliedImpulse) * compliance);
    const btScalar sum = btScalar(row.m_appliedImpulse) + delta;
    if (sum < row.m_lowerLimit)
    {
      delta = row.m_lowerLimit - btScalar(row.m_appliedImpulse);
      row.m_appliedImpulse = row.m_lowerLimit;
    }
    else
    {
      row.m_appliedImpulse = sum;
    }
    proxy.internalApplyImpulse(normal * proxy.internalGetInvMass(),
                               proxy_is_a ? row.m_angularComponentA : row.m_angularComponentB, delta);
  }
}
}  // namespace god_finger
