// Stage "record" of the world's step, right after Bullet's solve: what the solver did, kept for
// the next step and for output. Internal to physics.
//  - the impulses of the sub-god-objects and of the pads (sub_god_object_injection.h,
//    pad_constraints.h: the next step's warm start);
//  - an oriented finger's hand feels what its pads' rows gave the objects, turned back on it
//    (pad_state.h: the pad turns with the finger, so what it holds resists the finger's turn);
//  - each awake body's net force, m dv/dt over the step (BodyState::net_force).
// beforeSolve() records the velocities that net force starts from. Units: SI, world frame.
// Real-time safe.
#pragma once

namespace god_finger::internal
{
struct WorldCore;

// Before Bullet's step: the awake bodies' velocities, and the solver's counts restart.
void beforeSolve(WorldCore* core);
// After it (the step count not yet advanced: `core->steps` is the step just solved).
void recordImpulses(WorldCore* core);
// After the step count advanced: the awake bodies' net forces.
void recordNetForces(WorldCore* core);
}  // namespace god_finger::internal
