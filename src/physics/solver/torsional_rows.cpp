#include "solver/torsional_rows.h"

#include <cmath>

namespace god_finger::internal
{
void dropRowsThatCannotTurn(btAlignedObjectArray<btSolverConstraint>* rows)
{
  btAlignedObjectArray<btSolverConstraint>& torsional = *rows;
  for (int j = 0; j < torsional.size(); ++j)
  {
    if (!std::isfinite(torsional[j].m_jacDiagABInv))
    {
      torsional.swap(j, torsional.size() - 1);
      torsional.pop_back();
      --j;
    }
  }
}

void scaleToLever(btSolverConstraint* row)
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

void addExternalTorques(const btSolverBody& a, const btSolverBody& b, btSolverConstraint* row)
{
  const btScalar external = (a.m_originalBody ? row->m_relpos1CrossNormal.dot(a.m_externalTorqueImpulse) : 0.0) +
                            (b.m_originalBody ? row->m_relpos2CrossNormal.dot(b.m_externalTorqueImpulse) : 0.0);
  row->m_rhs -= external * row->m_jacDiagABInv;
}
}  // namespace god_finger::internal
