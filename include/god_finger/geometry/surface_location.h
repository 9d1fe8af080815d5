// A point on a triangle mesh: its triangle, barycentric coordinates and the feature (face,
// edge, vertex) it lies on.
//
// Feature tolerance: a point is on the edge opposite local vertex j when its barycentric
// coordinate j is <= feature_tolerance (dimensionless: the distance to the edge divided by
// the triangle's height above that edge). On two edges at once it is on their common
// vertex. The default, 1e-7, puts a point within 0.1 micrometre of an edge of a 1 m high
// triangle on that edge, and contacts reported by a physics engine on an edge or a corner
// (exact to about 1e-9 relative) are classified as such.
#pragma once

#include "god_finger/geometry/triangle_mesh.h"

#include <cstdint>

namespace god_finger
{
enum class FeatureKind : std::uint8_t
{
  kFace = 0,
  kEdge = 1,
  kVertex = 2,
};
const char* featureKindName(FeatureKind kind);

constexpr double kDefaultFeatureTolerance = 1e-7;

struct SurfaceLocation
{
  int face = -1;
  Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();  // sums to 1, each in [0, 1]
  Eigen::Vector3d point = Eigen::Vector3d::Zero();        // m, on the triangle
  FeatureKind feature = FeatureKind::kFace;
  // kEdge: local edge index k (edge from corner k to corner (k+1)%3); kVertex: local vertex
  // index j; kFace: -1.
  int feature_index = -1;
  double distance = 0.0;  // m, from the query point to `point`
};

// Closest point of triangle `face` to `query`, with barycentric coordinates. Exact for
// every query (no tolerance other than the feature classification).
SurfaceLocation locateOnFace(const TriangleMesh& mesh, int face, const Eigen::Vector3d& query,
                             double feature_tolerance = kDefaultFeatureTolerance);

// Barycentric coordinates (of a, b, c) of the point of triangle abc closest to `query`, each in
// [0, 1], summing to 1 (a degenerate triangle: its closest edge point).
Eigen::Vector3d closestBarycentric(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                   const Eigen::Vector3d& query);

// Classifies (and snaps to exact zeros) barycentric coordinates already known on a face.
SurfaceLocation locationFromBarycentric(const TriangleMesh& mesh, int face, const Eigen::Vector3d& barycentric,
                                        double feature_tolerance = kDefaultFeatureTolerance);
}  // namespace god_finger
