// Stage "coupling" of the world's step: the forces that act on the proxies and joints before
// Bullet's step. Internal to physics.
//  - each proxy: the virtual coupling k (p_I - p_GO) + b (v_I - v_GO), saturated
//    (haptics/virtual_coupling.h, with its interface's profile), on the proxy; the hand feels the
//    opposite (InterfaceState::user_force). A proxy letting go of a removed object is pulled
//    towards a target that reaches the hand over let_go_time instead. An oriented finger's
//    rotational coupling turns its proxy (oriented_finger.h), which cannot turn through what it
//    touched at the last step;
//  - the overlap pushes of the last step (overlap_push.h);
//  - every joint's friction and damping at its current speed (scene_joints.h).
// Units: SI, world frame. Real-time safe.
#pragma once

namespace god_finger::internal
{
struct WorldCore;

void applyCouplings(WorldCore* core);
}  // namespace god_finger::internal
