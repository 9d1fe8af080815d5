#include "grasp_constraint.h"

#include "bullet_helpers.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace god_finger
{
namespace
{
constexpr btScalar kParallel = 0.999;  // |cos| between two pads' axes: 2.6 degrees

// The body a pad's row turns: the side that is not the proxy.
bool bodyIsB(const btSolverConstraint& row, const btAlignedObjectArray<btSolverBody>& bodies)
{
  const btRigidBody* a = bodies[row.m_solverBodyIdA].m_originalBody;
  return a != nullptr && a->getUserIndex() == kKindProxy;
}

int bodyOf(const btSolverConstraint& row, const btAlignedObjectArray<btSolverBody>& bodies)
{
  return bodyIsB(row, bodies) ? row.m_solverBodyIdB : row.m_solverBodyIdA;
}

// The row's axis on the body, scaled to its lever (torsional_rows.h).
btVector3 bodyAxis(const btSolverConstraint& row, bool body_is_b)
{
  return body_is_b ? row.m_relpos2CrossNormal : row.m_relpos1CrossNormal;
}

// A pad's torque bound (N m s) for its normal row: its lever times the normal impulse, capped
// as Bullet caps a scaled row (at an impulse of 1, pad_torsion.cpp); zero while it does not push.
btScalar padBound(btScalar lever, const btSolverConstraint& contact)
{
  const btScalar normal = contact.m_appliedImpulse;
  return normal > 0.0 ? std::abs(lever) * std::min(normal, btScalar(1.0)) : btScalar(0.0);
}
}  // namespace

void GraspConstraints::collect(const std::vector<StepPad*>& pad_of_contact_row,
                               const btAlignedObjectArray<btSolverConstraint>& contacts,
                               btAlignedObjectArray<btSolverBody>& bodies,
                               btAlignedObjectArray<btSolverConstraint>* torsional_rows)
{
  btAlignedObjectArray<btSolverConstraint>& torsional = *torsional_rows;
  grasps_.clear();
  members_.clear();
  candidates_.clear();
  // The pads' twist rows: a pad's row about its contact's normal.
  for (int j = 0; j < torsional.size(); ++j)
  {
    const btSolverConstraint& row = torsional[j];
    const int contact = row.m_frictionIndex;
    if (contact < 0 || contact >= static_cast<int>(pad_of_contact_row.size()) || pad_of_contact_row[contact] == nullptr)
    {
      continue;
    }
    const btVector3& axis = row.m_relpos2CrossNormal;
    const btVector3& normal = contacts[contact].m_contactNormal1;
    if (axis.length() > 0.0 && std::abs(axis.dot(normal)) >= kParallel * axis.length() * normal.length())
    {
      candidates_.push_back(j);
    }
  }
  // Grouped by body and axis; a group of two or more is a grasp. Few pads: quadratic is fine.
  grouped_.assign(candidates_.size(), 0);
  removed_.clear();
  for (std::size_t i = 0; i < candidates_.size(); ++i)
  {
    if (grouped_[i] != 0)
    {
      continue;
    }
    const btSolverConstraint& first = torsional[candidates_[i]];
    const int body = bodyOf(first, bodies);
    const btVector3 g = bodyAxis(first, bodyIsB(first, bodies)).normalized();
    Grasp grasp;
    grasp.body = body;
    grasp.axis = g;
    grasp.first = static_cast<int>(members_.size());
    const std::size_t removed_before = removed_.size();
    for (std::size_t k = i; k < candidates_.size(); ++k)
    {
      const btSolverConstraint& row = torsional[candidates_[k]];
      const bool body_is_b = bodyIsB(row, bodies);
      const btVector3 axis = bodyAxis(row, body_is_b);
      if (grouped_[k] != 0 || bodyOf(row, bodies) != body || std::abs(axis.dot(g)) < kParallel * axis.length())
      {
        continue;
      }
      grouped_[k] = 1;
      Member member;
      member.pad = pad_of_contact_row[row.m_frictionIndex];
      member.contact_row = row.m_frictionIndex;
      member.lever = axis.dot(g);
      member.body_is_b = body_is_b;
      members_.push_back(member);
      removed_.push_back(candidates_[k]);
      // The row's velocity change (m/s at its lever) as the body's about g (rad/s), weighted
      // by lever; its warm impulse (already applied to the bodies) as torque about g.
      grasp.target += std::abs(member.lever) * (row.m_rhs / row.m_jacDiagABInv) / member.lever;
      grasp.mean_lever += std::abs(member.lever);
      grasp.impulse += member.lever * row.m_appliedImpulse;
      ++grasp.count;
    }
    if (grasp.count < 2)
    {
      // A single pad keeps its own row.
      members_.resize(grasp.first);
      removed_.resize(removed_before);
      continue;
    }
    grasp.target /= grasp.mean_lever;
    grasp.mean_lever /= grasp.count;
    const btRigidBody& rigid = *bodies[body].m_originalBody;
    grasp.angular_component = rigid.getInvInertiaTensorWorld() * g * rigid.getAngularFactor();
    grasp.inverse_effective = g.dot(rigid.getInvInertiaTensorWorld() * g);
    grasps_.push_back(grasp);
  }
  // The grasps' rows leave Bullet's pool, highest index first (nothing indexes the pool).
  std::sort(removed_.begin(), removed_.end(), std::greater<int>());
  for (const int j : removed_)
  {
    torsional.swap(j, torsional.size() - 1);
    torsional.pop_back();
  }
}

btScalar GraspConstraints::bound(const Grasp& grasp, const btAlignedObjectArray<btSolverConstraint>& contacts) const
{
  btScalar sum = 0.0;
  for (int m = grasp.first; m < grasp.first + grasp.count; ++m)
  {
    sum += padBound(members_[m].lever, contacts[members_[m].contact_row]);
  }
  return sum;
}

void GraspConstraints::apply(Grasp* grasp, btScalar impulse, btAlignedObjectArray<btSolverBody>& bodies)
{
  bodies[grasp->body].internalApplyImpulse(btVector3(0, 0, 0), grasp->angular_component, impulse);
  grasp->impulse += impulse;
}

btScalar GraspConstraints::iterate(const btAlignedObjectArray<btSolverConstraint>& contacts,
                                   btAlignedObjectArray<btSolverBody>& bodies)
{
  btScalar residual = 0.0;
  for (Grasp& grasp : grasps_)
  {
    // As Bullet solves a torsional row: only while its contacts push.
    const btScalar limit = bound(grasp, contacts);
    if (!(limit > 0.0) || !(grasp.inverse_effective > 0.0))
    {
      continue;
    }
    const btScalar velocity = grasp.axis.dot(bodies[grasp.body].internalGetDeltaAngularVelocity());
    const btScalar wanted = grasp.impulse + (grasp.target - velocity) / grasp.inverse_effective;
    const btScalar change = btClamped(wanted, -limit, limit) - grasp.impulse;
    apply(&grasp, change, bodies);
    const btScalar correction = change * grasp.inverse_effective * grasp.mean_lever;
    residual = std::max(residual, correction * correction);
  }
  return residual;
}

void GraspConstraints::finish(const btAlignedObjectArray<btSolverConstraint>& contacts,
                              btAlignedObjectArray<btSolverBody>& bodies)
{
  for (Grasp& grasp : grasps_)
  {
    // Within the bound of the final normal impulses (after the support passes), as a pad's row.
    const btScalar limit = bound(grasp, contacts);
    apply(&grasp, btClamped(grasp.impulse, -limit, limit) - grasp.impulse, bodies);
    const bool slipped = !(limit > 0.0) || std::abs(grasp.impulse) >= 0.999 * limit;
    for (int m = grasp.first; m < grasp.first + grasp.count; ++m)
    {
      const Member& member = members_[m];
      const btScalar share = limit > 0.0 ? padBound(member.lever, contacts[member.contact_row]) / limit : 0.0;
      // The pad's state keeps the torque on its manifold's body B.
      const btVector3 on_body = grasp.axis * (grasp.impulse * share);
      member.pad->state->torque_impulse += toEigen(member.body_is_b ? on_body : -on_body);
      if (slipped)
      {
        member.pad->state->twist_slipped = true;
      }
    }
  }
  grasps_.clear();
  members_.clear();
}
}  // namespace god_finger
