// An articulated object's joints in Bullet: a revolute or continuous joint as a
// btHingeConstraint, a prismatic one as a btSliderConstraint (rotation locked), between the
// child's rigid body and its parent's (the world's fixed body for the world). The joint's
// <dynamics> resist through the constraint's motor, solved with the contacts: each step the
// motor holds the relative speed at 0 with at most (friction + damping |speed|) of force or
// torque, so friction holds a joint still under a smaller load and damping never reverses the
// motion (stable at any damping, unlike an explicit -d v).
// Internal to physics. Frames: Bullet's body frames (centre of mass, principal axes); units SI.
// Building is not real-time safe; resistJointMotion and measureJoint are.
#pragma once

#include "scene_body.h"

#include "god_finger/physics/world_state.h"
#include "god_finger/scene/scene_description.h"

#include <btBulletDynamicsCommon.h>

#include <memory>

namespace god_finger::internal
{
// The constraint of `joint` between `parent` (null: the world, then `world_anchor`, a fixed body
// at the origin) and `child`, each with its SceneBody frames; the caller adds it to the world.
std::unique_ptr<btTypedConstraint> makeJointConstraint(const JointDescription& joint, const SceneBody* parent,
                                                       const SceneBody& child, btRigidBody* world_anchor);

// Sets the constraint's motor for the coming step of `time_step` s to the joint's resistance at
// its current relative speed (`state.velocity`).
void resistJointMotion(const JointDescription& joint, const JointState& state, double time_step,
                       btTypedConstraint* constraint);
}  // namespace god_finger::internal
