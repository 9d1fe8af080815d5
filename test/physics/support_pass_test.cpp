// The support pass (src/physics/solver/support_pass.h), a private piece of the physics tested on
// its own on Bullet's pools built by hand, with the row solver the solver passes it (Bullet's
// lower-limit row solver): a 20 g object pressed onto the ground by a 1 kg proxy, left sinking by
// the iterations, stops moving into the ground and the proxy stops moving into it while it is
// held (also with the rows' bodies the other way round and a compliant proxy row); an object
// heavier than the proxy, or one that touches nothing static, is left as the iterations left it.
#include "solver/support_pass.h"

#include "bullet_helpers.h"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

namespace god_finger
{
using namespace internal;  // the private pieces under test
namespace
{
const btVector3 kUp(0, 0, 1);

// A solver body as Bullet's initSolverBody makes it: `original` null for the fixed body every
// static object shares, inverse mass 1/m (0 for static and kinematic bodies), factors 1.
btSolverBody solverBody(btRigidBody* original)
{
  btSolverBody body;
  std::memset(static_cast<void*>(&body), 0, sizeof(body));
  body.m_originalBody = original;
  const btScalar inv_mass = original != nullptr ? original->getInvMass() : 0.0;
  body.m_invMass = btVector3(inv_mass, inv_mass, inv_mass);
  body.m_linearFactor = btVector3(1, 1, 1);
  body.m_angularFactor = btVector3(1, 1, 1);
  return body;
}

// A body of `mass` (0: static) tagged as a scene body or a proxy, as the world tags them.
struct Body
{
  Body(btScalar mass, int kind) : rigid(btRigidBody::btRigidBodyConstructionInfo(mass, nullptr, nullptr))
  {
    rigid.setUserIndex(kind);
  }
  btRigidBody rigid;
};

// A normal row as Bullet's setupContactConstraint makes it, through both centres (no turning):
// normal `normal_on_a` on A and its opposite on B (zero on the fixed body), effective mass
// 1 / (1/m_a + 1/m_b), target rhs = effective mass times minus the separating velocity
// `free_velocity` (m/s, negative approaching) the bodies had before the iterations, limits
// [0, 1e10], impulse `applied` (N s) as the iterations left it.
btSolverConstraint normalRow(const btAlignedObjectArray<btSolverBody>& bodies, int a, int b,
                             const btVector3& normal_on_a, btScalar free_velocity, btScalar applied)
{
  btSolverConstraint row;
  std::memset(static_cast<void*>(&row), 0, sizeof(row));
  row.m_solverBodyIdA = a;
  row.m_solverBodyIdB = b;
  row.m_contactNormal1 = bodies[a].m_originalBody != nullptr ? normal_on_a : btVector3(0, 0, 0);
  row.m_contactNormal2 = bodies[b].m_originalBody != nullptr ? -normal_on_a : btVector3(0, 0, 0);
  row.m_jacDiagABInv = 1 / (bodies[a].m_invMass.x() + bodies[b].m_invMass.x());
  row.m_rhs = -free_velocity * row.m_jacDiagABInv;
  row.m_lowerLimit = 0.0;
  row.m_upperLimit = 1e10;
  row.m_appliedImpulse = applied;
  return row;
}

// A row's separating velocity change since the step's start (m/s), as the row solvers read it.
btScalar velocityChange(const btAlignedObjectArray<btSolverBody>& bodies, const btSolverConstraint& row)
{
  const btSolverBody& a = bodies[row.m_solverBodyIdA];
  const btSolverBody& b = bodies[row.m_solverBodyIdB];
  return row.m_contactNormal1.dot(a.m_deltaLinearVelocity) + row.m_contactNormal2.dot(b.m_deltaLinearVelocity);
}

// Bullet's row solver the solver passes (ContactSolver: m_resolveSingleConstraintRowLowerLimit).
btSingleConstraintRowSolver bulletLowerLimitRowSolver()
{
  static btSequentialImpulseConstraintSolver bullet;
  return bullet.getActiveConstraintRowSolverLowerLimit();
}

// What a pass must leave as it was: every body's velocity change, every row's impulse.
struct Snapshot
{
  explicit Snapshot(const btAlignedObjectArray<btSolverBody>& bodies,
                    const btAlignedObjectArray<btSolverConstraint>& rows)
  {
    for (int i = 0; i < bodies.size(); ++i)
    {
      linear.push_back(bodies[i].m_deltaLinearVelocity);
      angular.push_back(bodies[i].m_deltaAngularVelocity);
    }
    for (int r = 0; r < rows.size(); ++r)
    {
      impulses.push_back(rows[r].m_appliedImpulse);
    }
  }
  std::vector<btVector3> linear;
  std::vector<btVector3> angular;
  std::vector<btScalar> impulses;
};

void expectUnchanged(const Snapshot& before, const btAlignedObjectArray<btSolverBody>& bodies,
                     const btAlignedObjectArray<btSolverConstraint>& rows)
{
  const Snapshot after(bodies, rows);
  for (size_t i = 0; i < before.linear.size(); ++i)
  {
    EXPECT_EQ(after.linear[i], before.linear[i]) << "body " << i;
    EXPECT_EQ(after.angular[i], before.angular[i]) << "body " << i;
  }
  EXPECT_EQ(after.impulses, before.impulses);
}

TEST(SupportPass, APressedLightObjectStopsSinkingAndTheProxyPressingItStops)
{
  // Body 0 the ground (Bullet's fixed body), 1 an object of 20 g (1/m = 50), 2 a proxy of 1 kg
  // (1/m = 1), stacked along +z. Before the iterations the object rests (0 m/s) and the proxy
  // presses down at 0.1 m/s. Row 0, object on ground: effective mass 1/50 = 0.02 kg, rhs 0.
  // Row 1, proxy on object: effective mass 1/51 kg, rhs 0.1/51 N s. The iterations left
  // impulses 0.049 and 0.05 N s: the object changed by 50 * (0.049 - 0.05) = -0.05 m/s (sinking
  // into the ground at 5 cm/s), the proxy by +0.05 m/s (still pressing at -0.05 m/s).
  Body object(0.02, kKindBody);
  Body proxy(1.0, kKindProxy);
  btAlignedObjectArray<btSolverBody> bodies;
  bodies.push_back(solverBody(nullptr));
  bodies.push_back(solverBody(&object.rigid));
  bodies.push_back(solverBody(&proxy.rigid));
  btAlignedObjectArray<btSolverConstraint> rows;
  rows.push_back(normalRow(bodies, 1, 0, kUp, 0.0, 0.049));
  rows.push_back(normalRow(bodies, 2, 1, kUp, -0.1, 0.05));
  bodies[1].m_deltaLinearVelocity = btVector3(0, 0, -0.05);
  bodies[2].m_deltaLinearVelocity = btVector3(0, 0, 0.05);

  std::vector<char> supported;
  supportPass(&bodies, &rows, bulletLowerLimitRowSolver(), &supported);
  EXPECT_EQ(supported.size(), 3u);
  // Row 0: delta = 0 - 0.02 * (-0.05) = 0.001 N s, impulse 0.05 N s; the object changes by
  // 50 * 0.001 = +0.05 m/s, to 0: it no longer moves into the ground.
  EXPECT_NEAR(rows[0].m_appliedImpulse, 0.05, 1e-15);
  EXPECT_NEAR(bodies[1].m_deltaLinearVelocity.z(), 0.0, 1e-15);
  EXPECT_NEAR(velocityChange(bodies, rows[0]), 0.0, 1e-15);
  // Row 1 with the object held: effective mass 1/(1/m_proxy) = 1 kg, target 0.1 m/s, delta =
  // 1 * (0.1 - 0.05 - 0) = 0.05 N s, impulse 0.1 N s (the proxy's whole momentum into the stack);
  // the proxy changes by +0.05 m/s to +0.1 m/s: -0.1 + 0.1 = 0, it stops moving into the object.
  // The held object's velocity is not changed by it.
  EXPECT_NEAR(rows[1].m_appliedImpulse, 0.1, 1e-15);
  EXPECT_NEAR(bodies[2].m_deltaLinearVelocity.z(), 0.1, 1e-15);
  EXPECT_NEAR(-0.1 + bodies[2].m_deltaLinearVelocity.z(), 0.0, 1e-15);
  EXPECT_NEAR(-0.1 + velocityChange(bodies, rows[1]), 0.0, 1e-15);
  EXPECT_NEAR(bodies[1].m_deltaLinearVelocity.z(), 0.0, 1e-15);
  // Nothing turns, nothing moves sideways, the ground stays.
  for (int i = 0; i < bodies.size(); ++i)
  {
    EXPECT_EQ(bodies[i].m_deltaAngularVelocity, btVector3(0, 0, 0));
    EXPECT_EQ(bodies[i].m_deltaLinearVelocity.x(), 0.0);
    EXPECT_EQ(bodies[i].m_deltaLinearVelocity.y(), 0.0);
  }
  EXPECT_EQ(bodies[0].m_deltaLinearVelocity, btVector3(0, 0, 0));

  // A second pass (WorldParams::support_passes = 2) finds both rows solved: no change.
  const Snapshot solved(bodies, rows);
  supportPass(&bodies, &rows, bulletLowerLimitRowSolver(), &supported);
  for (int r = 0; r < rows.size(); ++r)
  {
    EXPECT_NEAR(rows[r].m_appliedImpulse, solved.impulses[r], 1e-15);
  }
  EXPECT_NEAR(bodies[1].m_deltaLinearVelocity.z(), 0.0, 1e-15);
  EXPECT_NEAR(bodies[2].m_deltaLinearVelocity.z(), 0.1, 1e-15);
}

TEST(SupportPass, BodiesTheOtherWayRoundAndACompliantProxyRow)
{
  // The same stack with each row's bodies swapped: row 0 ground (a kinematic body, 1/m = 0) on
  // the object, row 1 object on the proxy (normal -z on A). Row 1 is compliant: compliance
  // c = 0.5 s/kg, stored as Bullet does, m_cfm = c * effective mass = 0.5/51.
  Body ground(0.0, kKindBody);
  Body object(0.02, kKindBody);
  Body proxy(1.0, kKindProxy);
  btAlignedObjectArray<btSolverBody> bodies;
  bodies.push_back(solverBody(&proxy.rigid));
  bodies.push_back(solverBody(&object.rigid));
  bodies.push_back(solverBody(&ground.rigid));
  btAlignedObjectArray<btSolverConstraint> rows;
  rows.push_back(normalRow(bodies, 2, 1, -kUp, 0.0, 0.049));
  rows.push_back(normalRow(bodies, 1, 0, -kUp, -0.1, 0.05));
  rows[1].m_cfm = 0.5 * rows[1].m_jacDiagABInv;
  bodies[1].m_deltaLinearVelocity = btVector3(0, 0, -0.05);
  bodies[0].m_deltaLinearVelocity = btVector3(0, 0, 0.05);

  std::vector<char> supported;
  supportPass(&bodies, &rows, bulletLowerLimitRowSolver(), &supported);
  // Row 0: as before, 0.001 N s more, the object at rest on the ground; the kinematic ground
  // (inverse mass 0) does not move.
  EXPECT_NEAR(rows[0].m_appliedImpulse, 0.05, 1e-15);
  EXPECT_NEAR(bodies[1].m_deltaLinearVelocity.z(), 0.0, 1e-15);
  EXPECT_EQ(bodies[2].m_deltaLinearVelocity, btVector3(0, 0, 0));
  // Row 1, object held: effective mass 1 / (1 + 0.5) = 2/3 kg, delta = 2/3 * (0.1 - 0.05 -
  // 0.05 * 0.5) = 1/60 N s, impulse 0.05 + 1/60 = 1/15 N s; the proxy changes to 0.05 + 1/60 =
  // 1/15 m/s, pressing at -0.1 + 1/15 = -1/30 m/s, which the compliance takes: the row's equation
  // velocity change + c * impulse = target holds, 1/15 + 0.5 * 1/15 = 0.1.
  EXPECT_NEAR(rows[1].m_appliedImpulse, 1.0 / 15.0, 1e-15);
  EXPECT_NEAR(bodies[0].m_deltaLinearVelocity.z(), 1.0 / 15.0, 1e-15);
  EXPECT_NEAR(velocityChange(bodies, rows[1]) + 0.5 * rows[1].m_appliedImpulse, 0.1, 1e-15);
  EXPECT_NEAR(bodies[1].m_deltaLinearVelocity.z(), 0.0, 1e-15);
}

TEST(SupportPass, AnObjectHeavierThanTheProxyIsLeftAsItWas)
{
  // A 2 kg object (1/m = 0.5) under the 1 kg proxy (1/m = 1): the iterations converge for it, so
  // the pass leaves its stack as they left it (impulses 0.01 and 0.05 N s, the object sinking at
  // 0.5 * (0.01 - 0.05) = -0.02 m/s, the proxy changed by +0.05 m/s).
  Body object(2.0, kKindBody);
  Body proxy(1.0, kKindProxy);
  btAlignedObjectArray<btSolverBody> bodies;
  bodies.push_back(solverBody(nullptr));
  bodies.push_back(solverBody(&object.rigid));
  bodies.push_back(solverBody(&proxy.rigid));
  btAlignedObjectArray<btSolverConstraint> rows;
  rows.push_back(normalRow(bodies, 1, 0, kUp, 0.0, 0.01));
  rows.push_back(normalRow(bodies, 2, 1, kUp, -0.1, 0.05));
  bodies[1].m_deltaLinearVelocity = btVector3(0, 0, -0.02);
  bodies[2].m_deltaLinearVelocity = btVector3(0, 0, 0.05);
  const Snapshot before(bodies, rows);
  std::vector<char> supported;
  supportPass(&bodies, &rows, bulletLowerLimitRowSolver(), &supported);
  expectUnchanged(before, bodies, rows);
  EXPECT_EQ(bodies[1].m_deltaLinearVelocity.z(), -0.02);
}

TEST(SupportPass, AnObjectThatTouchesNothingStaticIsLeftAsItWas)
{
  // A 20 g object lying on another 20 g object that rests on the ground, pressed by the 1 kg
  // proxy: the upper object touches nothing static and the lower one is pressed by no proxy, so
  // neither is held and nothing changes (impulses as the iterations left them, both sinking).
  Body lower(0.02, kKindBody);
  Body upper(0.02, kKindBody);
  Body proxy(1.0, kKindProxy);
  btAlignedObjectArray<btSolverBody> bodies;
  bodies.push_back(solverBody(nullptr));
  bodies.push_back(solverBody(&lower.rigid));
  bodies.push_back(solverBody(&upper.rigid));
  bodies.push_back(solverBody(&proxy.rigid));
  btAlignedObjectArray<btSolverConstraint> rows;
  rows.push_back(normalRow(bodies, 1, 0, kUp, 0.0, 0.048));
  rows.push_back(normalRow(bodies, 2, 1, kUp, 0.0, 0.049));
  rows.push_back(normalRow(bodies, 3, 2, kUp, -0.1, 0.05));
  bodies[1].m_deltaLinearVelocity = btVector3(0, 0, 50 * (0.048 - 0.049));  // -0.05 m/s
  bodies[2].m_deltaLinearVelocity = btVector3(0, 0, 50 * (0.049 - 0.05));   // -0.05 m/s
  bodies[3].m_deltaLinearVelocity = btVector3(0, 0, 0.05);
  const Snapshot before(bodies, rows);
  std::vector<char> supported;
  supportPass(&bodies, &rows, bulletLowerLimitRowSolver(), &supported);
  expectUnchanged(before, bodies, rows);

  // Pinched in the air between two proxies (no static body in the island): left as it was.
  Body pinched(0.02, kKindBody);
  Body left(1.0, kKindProxy);
  Body right(1.0, kKindProxy);
  btAlignedObjectArray<btSolverBody> air;
  air.push_back(solverBody(&left.rigid));
  air.push_back(solverBody(&pinched.rigid));
  air.push_back(solverBody(&right.rigid));
  btAlignedObjectArray<btSolverConstraint> pinch;
  pinch.push_back(normalRow(air, 0, 1, btVector3(-1, 0, 0), -0.1, 0.04));
  pinch.push_back(normalRow(air, 2, 1, btVector3(1, 0, 0), -0.1, 0.05));
  air[0].m_deltaLinearVelocity = btVector3(-0.04, 0, 0);
  air[1].m_deltaLinearVelocity = btVector3(50 * (0.04 - 0.05), 0, 0);  // -0.5 m/s
  air[2].m_deltaLinearVelocity = btVector3(0.05, 0, 0);
  const Snapshot in_air(air, pinch);
  supportPass(&air, &pinch, bulletLowerLimitRowSolver(), &supported);
  expectUnchanged(in_air, air, pinch);
}
}  // namespace
}  // namespace god_finger
