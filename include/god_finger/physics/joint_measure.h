// Where an articulated object's joint stands, from its bodies' states: the same answer in the
// physics (GodFingerWorld::jointState) and from a snapshot in the ROS nodes (joint_states).
//
// Units: rad and rad/s (revolute, continuous: the twist about the axis, in (-pi, pi]) or m and
// m/s (prismatic); 0 where the scene placed the child. Real-time safe.
#pragma once

#include "god_finger/physics/world_state.h"
#include "god_finger/scene/scene_description.h"

namespace god_finger
{
// `parent` is null for a joint to the world.
JointState measureJoint(const JointDescription& joint, const BodyState* parent, const BodyState& child);
}  // namespace god_finger
