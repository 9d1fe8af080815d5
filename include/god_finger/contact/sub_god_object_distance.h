// The distance the solver is given for one sub-god-object (docs/decisions.md, "Sub-god-object distances").
//
// The paper gives every sub-god-object the true contact's distance d. We add how far the object
// has tilted away from (or into) the pad at that point since the contact began:
//   d_i = d + n . (R l - l)
// with n the contact normal (out of the object), l the lever from the contact point to the
// sub-god-object and R the object's rotation relative to the pad since the contact began, all in
// one frame (the world's). Without the tilt term a tilt never shows as penetration, and the
// solver's small velocity errors add up to a slow, uncorrected tipping.
//
// Units: m (d, l, result); n unit length; R a rotation. Negative distances penetrate.
// Real-time safe (no allocation).
#pragma once

#include <Eigen/Core>

namespace god_finger
{
inline double tiltCorrectedDistance(double contact_distance, const Eigen::Vector3d& normal,
                                    const Eigen::Matrix3d& object_to_pad, const Eigen::Vector3d& lever)
{
  return contact_distance + normal.dot(object_to_pad * lever - lever);
}
}  // namespace god_finger
