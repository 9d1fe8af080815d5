// Bullet's torsional rows, corrected (src/physics/solver/torsional_rows.h), a private piece of the
// physics tested on its own on rows built by hand as Bullet's setupTorsionalFrictionConstraint
// builds them: a row between two bodies that cannot turn (effective mass 1 / 0) is dropped and
// every other row is kept, a row scaled to its lever L = 2 cm reads in m/s and N s and gives the
// bodies the same spin under Bullet's own row solver (its residual L times the one in rad/s), and
// this step's external torques enter the row's target, so that one solve stops the relative spin.
#include "solver/torsional_rows.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

namespace god_finger
{
using namespace internal;  // the private pieces under test
namespace
{
constexpr btScalar kLever = 0.02;  // m: the row's coefficient L

// A solver body that can turn (its angular factor 1) and has spun up to `spin` about +z; the
// row solvers move only its velocity change (m_deltaAngularVelocity), left at 0.
btSolverBody solverBody(btRigidBody* original, btScalar spin, btScalar external_spin = 0.0)
{
  btSolverBody body;
  std::memset(static_cast<void*>(&body), 0, sizeof(body));
  body.m_originalBody = original;
  body.m_linearFactor = btVector3(1, 1, 1);
  body.m_angularFactor = btVector3(1, 1, 1);
  body.m_angularVelocity = btVector3(0, 0, spin);
  body.m_externalTorqueImpulse = btVector3(0, 0, external_spin);  // rad/s: I^-1 torque dt
  return body;
}

// A torsional row about the normal +z as Bullet sets it up: axes -z on A and +z on B, angular
// components I^-1 times those axes (inverse inertias about z, 1/(kg m^2)), effective mass
// 1 / (sum of axis . I^-1 axis), target rhs = effective mass times minus the relative spin
// -spin_a + spin_b (Bullet leaves the external torques out), limits +-L, coefficient L.
btSolverConstraint torsionalRow(btScalar inv_inertia_a, btScalar inv_inertia_b, btScalar spin_a, btScalar spin_b,
                                btScalar lever, int tag = 0)
{
  btSolverConstraint row;
  std::memset(static_cast<void*>(&row), 0, sizeof(row));
  row.m_relpos1CrossNormal = btVector3(0, 0, -1);
  row.m_relpos2CrossNormal = btVector3(0, 0, 1);
  row.m_angularComponentA = btVector3(0, 0, -inv_inertia_a);
  row.m_angularComponentB = btVector3(0, 0, inv_inertia_b);
  const btScalar sum = inv_inertia_a + inv_inertia_b;  // 1/(kg m^2)
  row.m_jacDiagABInv = btScalar(1) / sum;              // 1/0 = inf when neither body can turn
  row.m_rhs = (spin_a - spin_b) * row.m_jacDiagABInv;  // N m s
  row.m_friction = lever;
  row.m_lowerLimit = -lever;
  row.m_upperLimit = lever;
  row.m_frictionIndex = tag;  // which row it is, for the test
  return row;
}

TEST(TorsionalRows, ARowBetweenBodiesThatCannotTurnIsDroppedAndTheOthersAreKept)
{
  // Rows 1 and 3 join two bodies without inverse inertia: 1 / (0 + 0) = inf. Rows 0, 2 and 4
  // have one body (100) or two (100, 400) that can turn: 1/100 = 0.01, 1/500 = 0.002 kg m^2.
  btAlignedObjectArray<btSolverConstraint> rows;
  rows.push_back(torsionalRow(100.0, 0.0, 0.3, 0.0, kLever, 0));
  rows.push_back(torsionalRow(0.0, 0.0, 0.0, 0.0, kLever, 1));
  rows.push_back(torsionalRow(100.0, 400.0, 0.3, -0.2, kLever, 2));
  rows.push_back(torsionalRow(0.0, 0.0, 0.0, 0.0, kLever, 3));
  rows.push_back(torsionalRow(0.0, 400.0, 0.0, -0.2, kLever, 4));
  ASSERT_TRUE(std::isinf(rows[1].m_jacDiagABInv));
  dropRowsThatCannotTurn(&rows);
  // The header promises no order (nothing indexes this pool): rows 0, 2 and 4 remain, each once
  // and untouched.
  ASSERT_EQ(rows.size(), 3);
  std::vector<int> kept;
  for (int j = 0; j < rows.size(); ++j)
  {
    kept.push_back(rows[j].m_frictionIndex);
    EXPECT_TRUE(std::isfinite(rows[j].m_jacDiagABInv));
  }
  std::sort(kept.begin(), kept.end());
  EXPECT_EQ(kept, (std::vector<int>{0, 2, 4}));
  for (int j = 0; j < rows.size(); ++j)
  {
    const btScalar expected_mass = rows[j].m_frictionIndex == 0 ? 0.01 : rows[j].m_frictionIndex == 2 ? 0.002 : 0.0025;
    EXPECT_NEAR(rows[j].m_jacDiagABInv, expected_mass, 1e-15);
    EXPECT_EQ(rows[j].m_friction, kLever);
  }

  // A pool of only such rows empties; an empty one stays empty.
  btAlignedObjectArray<btSolverConstraint> stuck;
  stuck.push_back(torsionalRow(0.0, 0.0, 0.0, 0.0, kLever, 0));
  stuck.push_back(torsionalRow(0.0, 0.0, 0.0, 0.0, kLever, 1));
  dropRowsThatCannotTurn(&stuck);
  EXPECT_EQ(stuck.size(), 0);
  dropRowsThatCannotTurn(&stuck);
  EXPECT_EQ(stuck.size(), 0);
}

TEST(TorsionalRows, ARowScaledToItsLeverReadsInMetresPerSecond)
{
  // I^-1 = 100 and 400 1/(kg m^2), spins 0.3 and -0.2 rad/s: effective mass 1/500 = 0.002 kg m^2,
  // relative spin -0.3 - 0.2 = -0.5 rad/s, rhs 0.002 * 0.5 = 0.001 N m s; warm start 0.0002 N m s;
  // Bullet's m_cfm (compliance times effective mass, a ratio) 0.1.
  btSolverConstraint row = torsionalRow(100.0, 400.0, 0.3, -0.2, kLever);
  row.m_appliedImpulse = 0.0002;
  row.m_cfm = 0.1;
  const btSolverConstraint unscaled = row;
  scaleToLever(&row);
  // L = 0.02 m: axes (0, 0, -+0.02) m, angular components 100 * 0.02 = 2 and 400 * 0.02 = 8,
  // effective mass 0.002 / 0.02^2 = 5 kg (= 1 / (0.02 * 2 + 0.02 * 8)), rhs 0.001 / 0.02 = 0.05 N s
  // (target 0.05 / 5 = 0.01 m/s = 0.02 m * 0.5 rad/s), warm start 0.0002 / 0.02 = 0.01 N s,
  // coefficient 1; the compliance ratio and the limits as they were.
  EXPECT_NEAR((row.m_relpos1CrossNormal - btVector3(0, 0, -0.02)).length(), 0.0, 1e-15);
  EXPECT_NEAR((row.m_relpos2CrossNormal - btVector3(0, 0, 0.02)).length(), 0.0, 1e-15);
  EXPECT_NEAR((row.m_angularComponentA - btVector3(0, 0, -2.0)).length(), 0.0, 1e-13);
  EXPECT_NEAR((row.m_angularComponentB - btVector3(0, 0, 8.0)).length(), 0.0, 1e-13);
  EXPECT_NEAR(row.m_jacDiagABInv, 5.0, 1e-12);
  EXPECT_NEAR(1.0 / (row.m_relpos1CrossNormal.dot(row.m_angularComponentA) +
                     row.m_relpos2CrossNormal.dot(row.m_angularComponentB)),
              5.0, 1e-12);
  EXPECT_NEAR(row.m_rhs, 0.05, 1e-15);
  EXPECT_NEAR(row.m_appliedImpulse, 0.01, 1e-15);
  EXPECT_EQ(row.m_friction, 1.0);
  EXPECT_EQ(row.m_cfm, 0.1);
  EXPECT_EQ(row.m_lowerLimit, unscaled.m_lowerLimit);
  EXPECT_EQ(row.m_upperLimit, unscaled.m_upperLimit);

  // The same solution under Bullet's row solver, its limits +-coefficient * normal impulse as
  // Bullet sets them each iteration (torque impulse <= L N before, impulse <= N after).
  btSequentialImpulseConstraintSolver bullet;
  const btSingleConstraintRowSolver solve = bullet.getActiveConstraintRowSolverGeneric();
  btRigidBody::btRigidBodyConstructionInfo info(1.0, nullptr, nullptr);
  btRigidBody body_a(info);
  btRigidBody body_b(info);
  for (const btScalar normal_impulse : {0.5, 0.02})  // N s: free, then bounding
  {
    btSolverConstraint before = unscaled;
    before.m_lowerLimit = -kLever * normal_impulse;
    before.m_upperLimit = kLever * normal_impulse;
    btSolverConstraint after = row;
    after.m_lowerLimit = -normal_impulse;
    after.m_upperLimit = normal_impulse;
    btSolverBody a0 = solverBody(&body_a, 0.3);
    btSolverBody b0 = solverBody(&body_b, -0.2);
    btSolverBody a1 = a0;
    btSolverBody b1 = b0;
    const btScalar residual_before = solve(a0, b0, before);
    const btScalar residual_after = solve(a1, b1, after);
    if (normal_impulse == 0.5)
    {
      // Free: delta = 0.001 - 0.0002 * 0.1 = 0.00098 N m s (0.049 N s scaled, = 0.00098 / 0.02), so
      // spin changes -100 * 0.00098 = -0.098 and 400 * 0.00098 = 0.392 rad/s; the residual is
      // 0.00098 / 0.002 = 0.49 rad/s before, 0.049 / 5 = 0.0098 m/s = 0.02 * 0.49 after.
      EXPECT_NEAR(before.m_appliedImpulse, 0.00118, 1e-15);
      EXPECT_NEAR(after.m_appliedImpulse, 0.059, 1e-14);
      EXPECT_NEAR(a0.m_deltaAngularVelocity.z(), -0.098, 1e-13);
      EXPECT_NEAR(b0.m_deltaAngularVelocity.z(), 0.392, 1e-13);
      EXPECT_NEAR(residual_before, 0.49, 1e-12);
      EXPECT_NEAR(residual_after, 0.0098, 1e-13);
    }
    else
    {
      // Bounded: 0.0002 + 0.00098 > 0.02 * 0.02 = 0.0004 N m s, so delta = 0.0004 - 0.0002 =
      // 0.0002 N m s (0.02 - 0.01 = 0.01 N s scaled): spin changes -0.02 and 0.08 rad/s.
      EXPECT_NEAR(before.m_appliedImpulse, 0.0004, 1e-15);
      EXPECT_NEAR(after.m_appliedImpulse, 0.02, 1e-15);
      EXPECT_NEAR(a0.m_deltaAngularVelocity.z(), -0.02, 1e-13);
      EXPECT_NEAR(b0.m_deltaAngularVelocity.z(), 0.08, 1e-13);
      EXPECT_NEAR(residual_after, kLever * residual_before, 1e-13);
    }
    EXPECT_NEAR(after.m_appliedImpulse * kLever, before.m_appliedImpulse, 1e-15);  // the same torque impulse
    EXPECT_NEAR(a1.m_deltaAngularVelocity.z(), a0.m_deltaAngularVelocity.z(), 1e-13);
    EXPECT_NEAR(b1.m_deltaAngularVelocity.z(), b0.m_deltaAngularVelocity.z(), 1e-13);
  }

  // A row without a lever (coefficient 0) is left as it was.
  btSolverConstraint no_lever = torsionalRow(100.0, 400.0, 0.3, -0.2, 0.0);
  const btSolverConstraint as_built = no_lever;
  scaleToLever(&no_lever);
  EXPECT_EQ(no_lever.m_relpos1CrossNormal, as_built.m_relpos1CrossNormal);
  EXPECT_EQ(no_lever.m_angularComponentA, as_built.m_angularComponentA);
  EXPECT_EQ(no_lever.m_angularComponentB, as_built.m_angularComponentB);
  EXPECT_EQ(no_lever.m_jacDiagABInv, as_built.m_jacDiagABInv);
  EXPECT_EQ(no_lever.m_rhs, as_built.m_rhs);
  EXPECT_EQ(no_lever.m_friction, 0.0);
}

TEST(TorsionalRows, ExternalTorquesEnterTheRowsTarget)
{
  btSequentialImpulseConstraintSolver bullet;
  const btSingleConstraintRowSolver solve = bullet.getActiveConstraintRowSolverGeneric();
  btRigidBody::btRigidBodyConstructionInfo info(1.0, nullptr, nullptr);
  btRigidBody body_a(info);
  btRigidBody body_b(info);

  // Two bodies, I^-1 = 100 and 400, spins 0.3 and -0.2 rad/s, scaled to L = 0.02 m as the solver
  // does first: effective mass 5 kg, rhs 0.05 N s. This step's torques spin them by a further
  // 0.1 and -0.05 rad/s: the row's velocity gains 0.02 * (-0.1) + 0.02 * (-0.05) = -0.003 m/s and
  // its target 5 * 0.003 = 0.015 N s: rhs 0.065 N s = 5 kg * 0.02 m * (0.4 + 0.25) rad/s.
  btSolverConstraint row = torsionalRow(100.0, 400.0, 0.3, -0.2, kLever);
  row.m_lowerLimit = -1e10;
  row.m_upperLimit = 1e10;
  scaleToLever(&row);
  btSolverBody a = solverBody(&body_a, 0.3, 0.1);
  btSolverBody b = solverBody(&body_b, -0.2, -0.05);
  addExternalTorques(a, b, &row);
  EXPECT_NEAR(row.m_rhs, 0.065, 1e-14);
  // One solve: 0.065 N s spins them by -2 * 0.065 = -0.13 and 8 * 0.065 = 0.52 rad/s, to
  // 0.3 + 0.1 - 0.13 = 0.27 and -0.2 - 0.05 + 0.52 = 0.27 rad/s: no relative spin left (without
  // the torques, 0.05 N s would leave 0.3 and 0.15 rad/s, their 0.15 rad/s difference).
  solve(a, b, row);
  const btScalar spin_a = a.m_angularVelocity.z() + a.m_externalTorqueImpulse.z() + a.m_deltaAngularVelocity.z();
  const btScalar spin_b = b.m_angularVelocity.z() + b.m_externalTorqueImpulse.z() + b.m_deltaAngularVelocity.z();
  EXPECT_NEAR(spin_a, 0.27, 1e-13);
  EXPECT_NEAR(spin_b, 0.27, 1e-13);

  // On a static body B (no original body: Bullet's fixed solver body, I^-1 = 0) B's torque field
  // is not read. Effective mass 0.01 / 0.02^2 = 25 kg, rhs 25 * 0.02 * 0.3 = 0.15 N s, plus
  // 25 * 0.02 * 0.1 = 0.05 N s from A's torque: 0.2 N s, which stops A (0.3 + 0.1 - 2 * 0.2 = 0).
  btSolverConstraint on_ground = torsionalRow(100.0, 0.0, 0.3, 0.0, kLever);
  on_ground.m_lowerLimit = -1e10;
  on_ground.m_upperLimit = 1e10;
  scaleToLever(&on_ground);
  btSolverBody a2 = solverBody(&body_a, 0.3, 0.1);
  btSolverBody ground = solverBody(nullptr, 0.0, 7.0);
  addExternalTorques(a2, ground, &on_ground);
  EXPECT_NEAR(on_ground.m_rhs, 0.2, 1e-13);
  solve(a2, ground, on_ground);
  EXPECT_NEAR(a2.m_angularVelocity.z() + a2.m_externalTorqueImpulse.z() + a2.m_deltaAngularVelocity.z(), 0.0, 1e-13);
}
}  // namespace
}  // namespace god_finger
