// Exact contact areas on spheres and cylinders: the walks follow the surface's geodesics in
// closed form instead of crossing the edges of a tessellation.
//
//  - Sphere (radius R, centred at the origin): great circles, p(s) = R (n0 cos(s/R) + t sin(s/R)).
//  - Cylinder (radius R, length L along z, centred): on the mantle, helices (straight lines on
//    the unrolled mantle); on a cap, straight lines; across a rim the direction is unfolded (the
//    component along the rim is kept, the other turns through the 90 degree fold). With the
//    default tau_a (60 degrees) a walk stops at a rim: the next surface is 90 degrees away.
//  - Boxes need no analytic walk: their walk mesh is their 12 triangles, on which the mesh
//    walk (unfold) is already the exact geodesic.
//
// The stops are the mesh walk's (surface_walk.h), taken exactly where the surface normal
// leaves tau_a or the friction cone about the contact normal (the mesh walk stops at the edge
// before the first face beyond). A radial vector whose walk cannot leave its start is dropped
// (kDropped), as the mesh walk drops one whose start face is beyond the limits. Results have
// no face: WalkResult::location.face is -1, location.point the position. crossings counts the
// rims crossed.
//
// Frames and units: the primitive's own frame (the geometry frame of scene_description.h), m,
// rad. Real-time safe: no allocation, no exceptions.
#pragma once

#include "god_finger/contact/contact_area.h"

namespace god_finger
{
struct PrimitiveSurface
{
  enum class Kind
  {
    kSphere,
    kCylinder,
  };
  Kind kind = Kind::kSphere;
  double radius = 0.0;  // m
  double length = 0.0;  // m, cylinder only (along z, centred at the origin)
};

// Walks `distance` (m, >= 0) from `start` (projected onto the surface) along `direction`
// (projected onto the tangent plane there, then normalised).
WalkResult walkPrimitive(const PrimitiveSurface& surface, const Eigen::Vector3d& start,
                         const Eigen::Vector3d& direction, double distance, const WalkLimits& limits);

// computeContactArea (contact_area.h) with exact walks: query.location.point is the contact
// point (its face is not read). `params` must be valid. Never allocates, never throws.
void computeContactArea(const PrimitiveSurface& surface, const ContactQuery& query, const ContactParams& params,
                        ContactAreaResult* out);
}  // namespace god_finger
