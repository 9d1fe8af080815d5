// The world's bounds: the box around the scene as loaded (every body's bounding box at its
// initial pose), grown by WorldParams::world_margin on every side. A dynamic body whose centre of
// mass leaves it (pushed off the table, it would fall forever and take the session's statistics
// with it) is caught: put back at its initial pose, at rest, as a reset puts it. Put back rather
// than put to sleep where it is: the scene stays whole for the user, who can touch the body again,
// and nothing keeps a body far away that the solver and the rviz view would chase. The world
// counts the catches per body (BodyState::left_world) and the nodes report them. A resting soft
// body is caught the same way (its Bullet body's origin; put back settled, soft_body.h). Internal to
// physics (god_finger_world.cpp).
//
// Units: m, world frame. Real-time safe: no allocation; catching clears the body's contact pairs
// (Bullet returns their manifolds to its pool).
#pragma once

#include <btBulletDynamicsCommon.h>

#include <Eigen/Geometry>

namespace god_finger::internal
{
// `scene_box` grown by `margin` (m, > 0) on every side.
Eigen::AlignedBox3d worldBounds(const Eigen::AlignedBox3d& scene_box, double margin);

// True when `point` (m, world) lies outside `bounds` or is not finite: a body there is caught.
bool outsideBounds(const Eigen::AlignedBox3d& bounds, const Eigen::Vector3d& point);

// If `rigid`'s centre of mass lies outside `bounds` (outsideBounds): puts it at `start` (its
// centre-of-mass frame in the world) with zero velocity and no pending force, updates its
// bounding box in `world` and drops its contact pairs; returns true. Else false, untouched.
bool catchIfOutside(const Eigen::AlignedBox3d& bounds, const btTransform& start, btRigidBody* rigid,
                    btDiscreteDynamicsWorld* world);
}  // namespace god_finger::internal
