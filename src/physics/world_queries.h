// What the world's state says of one body, joint or place, read from WorldCore (world_core.h):
// the public getters' and the stages' common reads. Internal to physics.
//
// Units: SI, world frame. Real-time safe, except deepestOverlap (it builds a probe shape).
#pragma once

#include "world_core.h"

#include "god_finger/physics/world_state.h"

#include <Eigen/Geometry>
#include <utility>

namespace god_finger::internal
{
// Scene body `body` (checked: std::out_of_range) as it is now.
BodyState bodyState(const WorldCore& core, int body);
// Scene joint `joint` (checked) as it stands now (joint_measure.h).
JointState jointState(const WorldCore& core, int joint);
// The body's geometry frame (its walk mesh's) in the world.
Eigen::Isometry3d geometryToWorld(const SceneBody& body);
// The body a proxy's sphere at `position` would start deepest in, and how deep (m): -1 when it
// overlaps none. Every body is probed, awake or dormant (contactPairTest needs no broadphase),
// as a finger: against a body's true surface (a cup's hollow).
std::pair<int, double> deepestOverlap(const WorldCore& core, const Eigen::Vector3d& position);
}  // namespace god_finger::internal
