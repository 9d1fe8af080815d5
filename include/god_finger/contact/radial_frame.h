// Radial vectors r_i of the god-finger method (paper, section 3.1): n unit vectors
// orthogonal to the contact normal, evenly spaced, starting at a first tangent t1.
//
// Continuity in time: no function of the normal alone gives a tangent that is continuous
// over the whole sphere (hairy-ball theorem), so the first tangent is transported from the
// previous step: the previous t1 is projected onto the new tangent plane and renormalised,
// which is the minimal rotation for small normal changes. With no usable previous tangent
// (first contact, or a normal change of ~90 degrees in one step) a deterministic basis of
// the normal alone is used (Duff et al., "Building an orthonormal basis, revisited", 2017),
// discontinuous only at n_z = -1.
#pragma once

#include <Eigen/Core>

namespace god_finger
{
// A unit vector orthogonal to `normal` (unit), a deterministic function of the normal.
Eigen::Vector3d defaultTangent(const Eigen::Vector3d& normal);

// `previous` carried onto the plane orthogonal to `normal`; defaultTangent(normal) when
// `previous` is zero, non-finite, or (nearly) parallel to the normal.
Eigen::Vector3d transportTangent(const Eigen::Vector3d& previous, const Eigen::Vector3d& normal);

// r_i = cos(2 pi i / n) t1 + sin(2 pi i / n) (normal x t1), i in [0, n).
Eigen::Vector3d radialVector(const Eigen::Vector3d& normal, const Eigen::Vector3d& first_tangent, int i, int n);
}  // namespace god_finger
