// The support pass: after Bullet's iterations, holds proxies pressing light objects onto static
// ones. The solver (contact_solver.h) runs it WorldParams::support_passes times. Internal to
// physics.
//
// Sequential impulses move about one object-mass of momentum per iteration through a stack
// proxy -> object -> static support, so an object much lighter than the proxy (20 g) sank into
// its support while pressed: 7 mm at 1/1000 of the proxy's mass after 60 iterations. After the
// regular iterations, `support_passes` passes (shock propagation, Guendelman et al. 2003,
// restricted to this stack) solve again, in order: each normal row between a dynamic object and
// a static body (the object stops moving into its support), then each normal row between a
// proxy and such a supported object with the object held fixed (the proxy stops moving into it;
// its push goes to the static support through the object, which it rests on). Friction rows
// and every other row are as Bullet solved them. Only objects lighter than the proxy are held
// (for heavier ones the iterations converge); one that touches nothing static (pinched in the
// air, lying on another dynamic object) is not.
//
// Units: Bullet's (SI, world frame). Real-time safe once `supported` has grown to the largest
// number of solver bodies.
#pragma once

#include <btBulletDynamicsCommon.h>

#include <vector>

namespace god_finger::internal
{
// One pass over the solve's `bodies` and normal rows `contacts` (Bullet's pools), solving a row
// against its lower limit with `solve_row_lower_limit` (Bullet's row solver); `supported` is
// scratch (per solver body).
void supportPass(btAlignedObjectArray<btSolverBody>* bodies, btAlignedObjectArray<btSolverConstraint>* contacts,
                 btSingleConstraintRowSolver solve_row_lower_limit, std::vector<char>* supported);
}  // namespace god_finger::internal
