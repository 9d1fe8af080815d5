#include "god_finger/scene/walk_mesh.h"

#include "god_finger/geometry/mesh_primitives.h"
#include "god_finger/mesh_io/mesh_loader.h"

#include <algorithm>
#include <cmath>

namespace god_finger
{
namespace
{
constexpr int kMaxIcosphereSubdivisions = 6;  // 81920 triangles
constexpr int kMinCylinderSegments = 16;
constexpr int kMaxCylinderSegments = 4096;
// Edge of an icosahedron inscribed in a unit sphere.
constexpr double kIcosahedronEdge = 1.0514622242382672;
}  // namespace

int walkSphereSubdivisions(double radius, double max_edge)
{
  int subdivisions = 0;
  while (subdivisions < kMaxIcosphereSubdivisions && radius * kIcosahedronEdge / std::pow(2.0, subdivisions) > max_edge)
  {
    ++subdivisions;
  }
  return subdivisions;
}

int walkCylinderSegments(double radius, double max_edge)
{
  const double segments = std::ceil(2.0 * M_PI * radius / max_edge);
  return static_cast<int>(std::clamp(segments, double(kMinCylinderSegments), double(kMaxCylinderSegments)));
}

TriangleMesh makeWalkMesh(const Geometry& geometry, double max_edge)
{
  switch (geometry.kind)
  {
    case GeometryKind::kBox:
      return TriangleMesh::build(makeBox(geometry.size / 2.0));
    case GeometryKind::kSphere:
      return TriangleMesh::build(makeIcosphere(geometry.radius, walkSphereSubdivisions(geometry.radius, max_edge)));
    case GeometryKind::kCylinder:
      return TriangleMesh::build(
          makeCylinder(geometry.radius, geometry.length, walkCylinderSegments(geometry.radius, max_edge)));
    case GeometryKind::kMesh:
      return loadTriangleMesh(geometry.mesh_path, geometry.scale);
  }
  return TriangleMesh::build(makeBox(Eigen::Vector3d::Constant(0.5)));
}
}  // namespace god_finger
