#include "solver/contact_solver.h"

#include "bullet_helpers.h"
#include "solver/pad_torsion.h"
#include "solver/support_pass.h"
#include "solver/torsional_rows.h"

namespace god_finger::internal
{
btScalar ContactSolver::solveGroup(btCollisionObject** bodies, int num_bodies, btPersistentManifold** manifolds,
                                   int num_manifolds, btTypedConstraint** constraints, int num_constraints,
                                   const btContactSolverInfo& info, btIDebugDraw* debug_draw, btDispatcher* dispatcher)
{
  for (int i = 0; i < num_manifolds; ++i)
  {
    if (manifolds[i]->getBody0()->getUserIndex() == kKindProxy ||
        manifolds[i]->getBody1()->getUserIndex() == kKindProxy)
    {
      proxy_points_ += manifolds[i]->getNumContacts();
    }
  }
  return btSequentialImpulseConstraintSolver::solveGroup(bodies, num_bodies, manifolds, num_manifolds, constraints,
                                                         num_constraints, info, debug_draw, dispatcher);
}

StepPad* ContactSolver::padOf(const btSolverConstraint& row) const
{
  const int contact = row.m_frictionIndex;
  if (contact < 0 || contact >= static_cast<int>(pad_of_contact_row_.size()))
  {
    return nullptr;
  }
  return pad_of_contact_row_[contact];
}

void ContactSolver::convertContacts(btPersistentManifold** manifolds, int num_manifolds,
                                    const btContactSolverInfo& info)
{
  btSequentialImpulseConstraintSolver::convertContacts(manifolds, num_manifolds, info);
  pad_of_contact_row_.clear();
  if (pads_ != nullptr && !pads_->empty())
  {
    pad_of_contact_row_.resize(m_tmpSolverContactConstraintPool.size());
    for (int j = 0; j < m_tmpSolverContactConstraintPool.size(); ++j)
    {
      pad_of_contact_row_[j] = pads_->find(m_tmpSolverContactConstraintPool[j].m_originalContactPoint);
    }
  }
  btAlignedObjectArray<btSolverConstraint>& torsional = m_tmpSolverContactRollingFrictionConstraintPool;
  dropRowsThatCannotTurn(&torsional);
  rows_ += m_tmpSolverContactConstraintPool.size() + m_tmpSolverContactFrictionConstraintPool.size() + torsional.size();
  for (int j = 0; j < torsional.size(); ++j)
  {
    btSolverConstraint& row = torsional[j];
    scaleToLever(&row);
    btSolverBody& a = m_tmpSolverBodyPool[row.m_solverBodyIdA];
    btSolverBody& b = m_tmpSolverBodyPool[row.m_solverBodyIdB];
    addExternalTorques(a, b, &row);
    const StepPad* pad = padOf(row);
    if (pad != nullptr)
    {
      preparePadTorsionalRow(*pad, m_tmpSolverContactConstraintPool[row.m_frictionIndex], info, &a, &b, &row);
    }
  }
}

btScalar ContactSolver::solveGroupCacheFriendlyFinish(btCollisionObject** bodies, int num_bodies,
                                                      const btContactSolverInfo& info)
{
  for (int j = 0; j < m_tmpSolverContactRollingFrictionConstraintPool.size(); ++j)
  {
    btSolverConstraint& row = m_tmpSolverContactRollingFrictionConstraintPool[j];
    StepPad* pad = padOf(row);
    if (pad != nullptr)
    {
      finishPadTorsionalRow(m_tmpSolverContactConstraintPool[row.m_frictionIndex],
                            &m_tmpSolverBodyPool[row.m_solverBodyIdA], &m_tmpSolverBodyPool[row.m_solverBodyIdB], &row,
                            pad);
    }
  }
  return btSequentialImpulseConstraintSolver::solveGroupCacheFriendlyFinish(bodies, num_bodies, info);
}

btScalar ContactSolver::solveGroupCacheFriendlyIterations(btCollisionObject** bodies, int num_bodies,
                                                          btPersistentManifold** manifolds, int num_manifolds,
                                                          btTypedConstraint** constraints, int num_constraints,
                                                          const btContactSolverInfo& info, btIDebugDraw* debug_draw)
{
  const btScalar residual = btSequentialImpulseConstraintSolver::solveGroupCacheFriendlyIterations(
      bodies, num_bodies, manifolds, num_manifolds, constraints, num_constraints, info, debug_draw);
  for (int pass = 0; pass < support_passes_; ++pass)
  {
    supportPass(&m_tmpSolverBodyPool, &m_tmpSolverContactConstraintPool, m_resolveSingleConstraintRowLowerLimit,
                &supported_);
  }
  return residual;
}
}  // namespace god_finger::internal
