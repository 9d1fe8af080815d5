#include "solver/support_pass.h"

#include "bullet_helpers.h"

namespace god_finger::internal
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
}  // namespace

void supportPass(btAlignedObjectArray<btSolverBody>* solver_bodies, btAlignedObjectArray<btSolverConstraint>* contacts,
                 btSingleConstraintRowSolver solve_row_lower_limit, std::vector<char>* supported)
{
  btAlignedObjectArray<btSolverBody>& bodies = *solver_bodies;
  btAlignedObjectArray<btSolverConstraint>& rows = *contacts;
  const int row_count = rows.size();
  const int body_count = bodies.size();
  // Per solver body: 1 rests on something static, 2 also pressed by a heavier proxy (held).
  // The buffer grows once.
  std::vector<char>& state = *supported;
  state.assign(body_count, 0);
  for (int r = 0; r < row_count; ++r)
  {
    const btSolverConstraint& row = rows[r];
    const btSolverBody& a = bodies[row.m_solverBodyIdA];
    const btSolverBody& b = bodies[row.m_solverBodyIdB];
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
    const btSolverConstraint& row = rows[r];
    const btSolverBody& a = bodies[row.m_solverBodyIdA];
    const btSolverBody& b = bodies[row.m_solverBodyIdB];
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
    btSolverConstraint& row = rows[r];
    btSolverBody& a = bodies[row.m_solverBodyIdA];
    btSolverBody& b = bodies[row.m_solverBodyIdB];
    if ((state[row.m_solverBodyIdA] == 2 && isStatic(b)) || (isStatic(a) && state[row.m_solverBodyIdB] == 2))
    {
      solve_row_lower_limit(a, b, row);
    }
  }
  // A proxy stops moving into a held object.
  for (int r = 0; r < row_count; ++r)
  {
    btSolverConstraint& row = rows[r];
    btSolverBody& a = bodies[row.m_solverBodyIdA];
    btSolverBody& b = bodies[row.m_solverBodyIdB];
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
}  // namespace god_finger::internal
