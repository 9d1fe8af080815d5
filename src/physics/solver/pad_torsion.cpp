#include "solver/pad_torsion.h"

#include "bullet_helpers.h"

#include <algorithm>
#include <cmath>

namespace god_finger::internal
{
namespace
{
// A torsional row's bound for its contact's normal impulse, as Bullet's iterations set it
// (btSequentialImpulseConstraintSolver::solveSingleIteration: coefficient x normal impulse,
// capped at the coefficient; zero while the contact does not push).
btScalar torsionalBound(const btSolverConstraint& row, const btSolverConstraint& contact)
{
  const btScalar normal = contact.m_appliedImpulse;
  return normal > 0.0 ? std::min(row.m_friction * normal, row.m_friction) : btScalar(0.0);
}
}  // namespace

void preparePadTorsionalRow(const StepPad& pad, const btSolverConstraint& contact, const btContactSolverInfo& info,
                            btSolverBody* a, btSolverBody* b, btSolverConstraint* row)
{
  // The row turns B relative to A about `axis`; towards the anchor at the friction ERP.
  const btVector3& axis = row->m_relpos2CrossNormal;
  const double turned = toBullet(pad.turn_since_anchor).dot(axis);
  row->m_rhs -= turned * info.m_frictionERP / info.m_timeStep * row->m_jacDiagABInv;
  if (!pad.follow_velocity.isZero(0.0))
  {
    row->m_rhs += toBullet(pad.follow_velocity).dot(axis) * row->m_jacDiagABInv;
  }
  // Warm start inside this step's bound (from the normal row's warm impulse, as the
  // iterations will bound it).
  if (info.m_solverMode & SOLVER_USE_WARMSTARTING)
  {
    const btScalar bound = torsionalBound(*row, contact);
    // The torque impulse about the scaled axis (L u), in the row's units (impulse at the lever L).
    const btScalar warm = btClamped<btScalar>(
        toBullet(pad.warm_torque_impulse).dot(axis) / axis.length2() * info.m_warmstartingFactor, -bound, bound);
    row->m_appliedImpulse = warm;
    a->internalApplyImpulse(row->m_contactNormal1 * a->internalGetInvMass(), row->m_angularComponentA, warm);
    b->internalApplyImpulse(row->m_contactNormal2 * b->internalGetInvMass(), row->m_angularComponentB, warm);
  }
}

void finishPadTorsionalRow(const btSolverConstraint& contact, btSolverBody* a, btSolverBody* b, btSolverConstraint* row,
                           StepPad* pad)
{
  // Within the bound of the final normal impulse (after the support passes): Bullet solves a
  // torsional row only while its contact pushes, so a warm-started impulse would otherwise
  // stay on a contact that let go.
  const btScalar bound = torsionalBound(*row, contact);
  const btScalar clamped = btClamped<btScalar>(row->m_appliedImpulse, -bound, bound);
  if (clamped != row->m_appliedImpulse)
  {
    const btScalar change = clamped - row->m_appliedImpulse;
    a->internalApplyImpulse(row->m_contactNormal1 * a->internalGetInvMass(), row->m_angularComponentA, change);
    b->internalApplyImpulse(row->m_contactNormal2 * b->internalGetInvMass(), row->m_angularComponentB, change);
    row->m_appliedImpulse = clamped;
  }
  pad->state->torque_impulse += toEigen(row->m_relpos2CrossNormal) * row->m_appliedImpulse;
  // At its bound: the pad slipped about this axis (or let go).
  if (!(bound > 0.0) || std::abs(row->m_appliedImpulse) >= 0.999 * bound)
  {
    pad->state->twist_slipped = true;
  }
}
}  // namespace god_finger::internal
