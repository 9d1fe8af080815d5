// The finger pad's shape under uniform pressure over the area its sub-god-objects bound: where
// the pad constraint (pad_constraints.h) puts its point and how far its torsional rows reach.
// Internal to physics.
//
// Units: SI, world frame. Real-time safe (no allocation).
#pragma once

#include "god_finger/physics/world_state.h"

#include <Eigen/Core>

namespace god_finger::internal
{
struct PadGeometry
{
  Eigen::Vector3d centre_of_pressure = Eigen::Vector3d::Zero();  // m, world, in the tangent plane at the contact
  double torsional_lever = 0.0;  // m: (1/A) integral of |r - cop| dA; (2/3) a for a disk of radius a
  double support_radius = 0.0;   // m: mean distance from the centre of pressure to the area's rim; a for a disk
};

// From the contact point `centre` (m, world), the normal and the area's kept sub-god-objects in
// walk order (a star-shaped polygon around `centre`). Fewer than 3 sub-god-objects: a point
// (levers zero, centre of pressure at `centre`).
PadGeometry padGeometry(const Eigen::Vector3d& centre, const Eigen::Vector3d& normal, const WorldContactArea& area);
}  // namespace god_finger::internal
