// The pad constraint's torsional rows in the solve (pad_constraints.h): what the solver
// (contact_solver.h) adds to Bullet's rows of a pad, already scaled to their lever and given
// this step's external torques (torsional_rows.h). Internal to physics.
//
// Before the iterations, each row is corrected towards the pad's orientation anchor at Bullet's
// friction ERP (an oriented finger's rows also given the finger's own turning speed as their target)
// and warm-started from the pad's last torque impulse; after them (and the support
// passes) it is bounded by its contact's final normal impulse, its impulse goes back to the
// pad's state, and a row at its bound marks the pad's twist as slipped (its anchor is let go in
// the next step).
//
// Units: Bullet's (SI, world frame); a row's impulse is at its lever (N s). Real-time safe.
#pragma once

#include "solver/pad_constraints.h"

#include <btBulletDynamicsCommon.h>

namespace god_finger::internal
{
// Before the iterations: one row of `pad` between solver bodies `a` and `b`, whose contact row
// (the normal row) is `contact`.
void preparePadTorsionalRow(const StepPad& pad, const btSolverConstraint& contact, const btContactSolverInfo& info,
                            btSolverBody* a, btSolverBody* b, btSolverConstraint* row);

// After the iterations: the row within the bound of `contact`'s final normal impulse; its
// impulse into the pad's state, and slip detection.
void finishPadTorsionalRow(const btSolverConstraint& contact, btSolverBody* a, btSolverBody* b, btSolverConstraint* row,
                           StepPad* pad);
}  // namespace god_finger::internal
