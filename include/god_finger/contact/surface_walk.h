// Algorithm 1 of the paper: one sub-god-object walks a distance d over the mesh from the
// contact point along a radial vector, crossing edges through the neighbour table.
//
// Choices where the paper is silent (tested in test/contact/surface_walk_test.cpp):
//  - The walk is exact in barycentric coordinates: the point never leaves the surface, and
//    an edge point is carried to the neighbour with the same edge parameter.
//  - A face is entered only if sign * (face normal . contact normal) > cos(min(tau_a,
//    atan(theta))) (the paper's strict "<" on the angle). `sign` is that of the start face
//    normal against the contact normal, so an open surface touched from its back side works.
//  - Project variant: if the projected direction does not enter the new face (a fold of 90
//    degrees or more), the walk stops on the edge: kDirectionLost.
//  - Through a vertex: the walk continues into the incident face whose corner wedge contains
//    the direction carried onto it (minimal rotation from the old face for kUnfold, projection
//    for kProject), the most central one if several do. If none does (a convex corner: a
//    geodesic cannot pass through it), it stops on the vertex: kVertexBlocked.
//  - Boundary and non-manifold edges stop the walk on the edge.
//  - Directions within 1e-12 rad of an edge walk along the edge rather than bouncing across it.
//  - A hard cap (ContactParams::max_crossings) on edges crossed; a walk that makes no
//    progress over 64 crossings in a row (a degenerate fan) stops too: kCrossingCap.
#pragma once

#include "god_finger/contact/contact_params.h"
#include "god_finger/geometry/surface_location.h"

#include <cstdint>
#include <optional>

namespace god_finger
{
enum class WalkStop : std::uint8_t
{
  kDistanceReached = 0,  // walked the full d_i
  kAngleLimit,           // next face's normal beyond tau_a
  kFrictionLimit,        // next face's normal outside the friction cone atan(theta)
  kBoundaryEdge,         // hole or open border
  kNonManifoldEdge,      // more than two faces on the edge
  kVertexBlocked,        // reached a vertex no incident face can be entered from
  kDirectionLost,        // direction degenerate on the new face (projection variant at a fold)
  kCrossingCap,          // max_crossings reached, or no progress
  kDropped,              // start: the radial vector's face is beyond tau_a or the friction cone
  kInvalidInput,         // non-finite input, a location not on the mesh, or barycentric coordinates
                         // that do not sum to 1 or lie outside [0, 1] (kBarycentricTolerance)
};
const char* walkStopName(WalkStop stop);

// How far a start location's barycentric coordinates may sum from 1, or fall below 0
// (dimensionless): a location snapped to a feature (surface_location.h, feature tolerance 1e-7)
// is off by at most 2e-7; more is not a point of the face, and walkSurface refuses it.
constexpr double kBarycentricTolerance = 1e-6;

struct WalkResult
{
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // m, on the surface
  SurfaceLocation location;                            // where it ended (face, feature)
  double walked = 0.0;                                 // m, along the surface
  int crossings = 0;                                   // edges crossed
  WalkStop stop = WalkStop::kDistanceReached;
};

// Thresholds of a walk, precomputed once per contact from ContactParams.
struct WalkLimits
{
  Eigen::Vector3d contact_normal = Eigen::Vector3d::UnitZ();  // unit, outward
  double normal_sign = 1.0;      // +1 or -1: orientation of the mesh against the contact normal
  double cos_max_angle = 0.5;    // cos(tau_a)
  double cos_friction = 0.7071;  // cos(atan(theta)); -2 when theta = +inf
  WalkVariant variant = WalkVariant::kUnfold;
  int max_crossings = 4096;
};
WalkLimits makeWalkLimits(const ContactParams& params, const Eigen::Vector3d& contact_normal, double normal_sign);

// Algorithm 1's test of the next face (or a primitive's next surface): none when a surface of unit
// normal `normal` may be entered, its normal within tau_a of the contact normal and inside the
// friction cone; else why not (kAngleLimit, then kFrictionLimit). Real-time safe.
inline std::optional<WalkStop> surfaceLimit(const Eigen::Vector3d& normal, const WalkLimits& limits)
{
  const double c = limits.normal_sign * normal.dot(limits.contact_normal);
  if (!(c > limits.cos_max_angle))
  {
    return WalkStop::kAngleLimit;
  }
  if (!(c > limits.cos_friction))
  {
    return WalkStop::kFrictionLimit;
  }
  return std::nullopt;
}

// Picks the face to start from at `start` (on a face, an edge or a vertex) for a direction
// given in the plane orthogonal to `direction_normal`, and carries the direction onto it.
// Returns false (and `stop` says why) when the radial vector is dropped.
bool chooseStartFace(const TriangleMesh& mesh, const SurfaceLocation& start, const Eigen::Vector3d& direction,
                     const Eigen::Vector3d& direction_normal, const WalkLimits& limits, SurfaceLocation* start_on_face,
                     Eigen::Vector3d* direction_on_face, WalkStop* stop);

// Walks `distance` (m, >= 0) from `start` along `direction` (unit, in the plane of
// start.face). Never allocates.
[[nodiscard]] WalkResult walkSurface(const TriangleMesh& mesh, const SurfaceLocation& start,
                                     const Eigen::Vector3d& direction, double distance, const WalkLimits& limits);
}  // namespace god_finger
