#include "god_finger/scene/scene_budget.h"

#include "god_finger/scene/walk_mesh.h"
#include "god_finger/support/memory_budget.h"

#include <string>

namespace god_finger
{
namespace
{
// Bytes a piece's walk tessellation needs (a mesh file's triangles are checked when it is read).
std::uint64_t walkBytes(const Geometry& geometry, double max_walk_edge)
{
  std::uint64_t vertices = 8;
  std::uint64_t triangles = 12;
  if (geometry.kind == GeometryKind::kSphere)
  {
    const std::uint64_t faces = 20ull << (2 * walkSphereSubdivisions(geometry.radius, max_walk_edge));
    vertices = faces / 2 + 2;
    triangles = faces;
  }
  else if (geometry.kind == GeometryKind::kCylinder)
  {
    const std::uint64_t segments = static_cast<std::uint64_t>(walkCylinderSegments(geometry.radius, max_walk_edge));
    vertices = 2 * segments + 2;
    triangles = 4 * segments;
  }
  else if (geometry.kind == GeometryKind::kMesh)
  {
    vertices = 0;
    triangles = 0;
  }
  return estimatedMeshBytes(vertices, triangles);
}
}  // namespace

std::uint64_t estimatedSceneBytes(const SceneDescription& scene, double max_walk_edge)
{
  std::uint64_t bytes = 0;
  for (const BodyDescription& body : scene.bodies)
  {
    bytes += kBytesPerBody + walkBytes(body.geometry, max_walk_edge);
    for (const BodyPart& part : body.more_parts)
    {
      bytes += 2 * walkBytes(part.geometry, max_walk_edge);  // its own and its copy in the union
    }
  }
  return bytes;
}

void checkSceneFits(const SceneDescription& scene, double max_walk_edge)
{
  const std::string name = "scene '" + scene.name + "' has " + std::to_string(scene.bodies.size()) + " bodies";
  if (scene.bodies.size() > static_cast<std::size_t>(kMaxBodies))
  {
    throw ResourceLimitError(name + ", more than the limit of " + std::to_string(kMaxBodies));
  }
  const std::uint64_t needed = estimatedSceneBytes(scene, max_walk_edge);
  const MemoryLimit limit = memoryLimit();
  if (needed > limit.bytes)
  {
    throw ResourceLimitError(name + ": they and their walk meshes need about " +
                             formatBytes(static_cast<double>(needed)) + ", more than the limit of " +
                             formatBytes(static_cast<double>(limit.bytes)) + " (" + limit.source + ")");
  }
}
}  // namespace god_finger
