// Bullet's torsional rows (spinning and rolling friction), corrected for every contact: the
// solver (contact_solver.h) applies these to each such row after Bullet set it up. Internal to
// physics.
//
// Bullet sets these rows up without the step's external torques, which they then meet one step
// late, and without an effective mass when neither body can turn (0/0). Here every such row
// sees this step's external torques and a row between two bodies that cannot turn is dropped.
//
// Every torsional row is solved at its lever (scaleToLever): Bullet measures a row's residual in
// its own velocity, rad/s for these rows, so the iterations' tolerance (m/s) asked them for 10 um/s
// read as 10 urad/s, and they ran every iteration (god_finger 54 per step where god_object needs
// 26). Scaled by the row's coefficient L (m), a row's velocity is L times the angular one (m/s, the
// speed at the lever) and its impulse is the torque impulse over L, bounded by the normal impulse:
// the same solution, one tolerance for every row.
//
// Units: Bullet's (SI, world frame). Real-time safe (no allocation).
#pragma once

#include <btBulletDynamicsCommon.h>

namespace god_finger::internal
{
// Drops the rows of `rows` without an effective mass (neither body can turn: a proxy on a static
// object). Kept with a zero effective mass, Bullet's row solve would return 0 / 0 as its
// residual and the iterations would never stop early. Nothing indexes this pool.
void dropRowsThatCannotTurn(btAlignedObjectArray<btSolverConstraint>* rows);

// Scales a torsional row (coefficient L > 0, m) so that its velocity is L times its angular
// velocity (m/s) and its impulse the torque impulse over L (N s); its coefficient becomes 1.
void scaleToLever(btSolverConstraint* row);

// Adds this step's external torques on the row's bodies `a` and `b` (which Bullet leaves out of
// these rows' velocity) to the row's target.
void addExternalTorques(const btSolverBody& a, const btSolverBody& b, btSolverConstraint* row);
}  // namespace god_finger::internal
