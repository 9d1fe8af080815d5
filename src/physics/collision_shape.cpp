#include "collision_shape.h"

#include <BulletCollision/CollisionShapes/btShapeHull.h>
#include <LinearMath/btConvexHullComputer.h>

namespace god_finger::internal
{
namespace
{
// Convex hull volume of a point set (m^3).
double hullVolume(const std::vector<btScalar>& coordinates)
{
  btConvexHullComputer hull;
  hull.compute(coordinates.data(), 3 * sizeof(btScalar), static_cast<int>(coordinates.size() / 3), 0.0, 0.0);
  double volume = 0.0;
  for (int face = 0; face < hull.faces.size(); ++face)
  {
    const btConvexHullComputer::Edge* first = &hull.edges[hull.faces[face]];
    const btVector3& origin = hull.vertices[first->getSourceVertex()];
    const btConvexHullComputer::Edge* edge = first->getNextEdgeOfFace();
    while (edge->getTargetVertex() != first->getSourceVertex())
    {
      const btVector3& b = hull.vertices[edge->getSourceVertex()];
      const btVector3& c = hull.vertices[edge->getTargetVertex()];
      volume += origin.dot(b.cross(c)) / 6.0;
      edge = edge->getNextEdgeOfFace();
    }
  }
  return volume;
}

// A convex hull whose box reaches kHullPairReach (collision_shape.h) beyond its points and margin.
class ReachingHull : public btConvexHullShape
{
 public:
  void getAabb(const btTransform& transform, btVector3& min, btVector3& max) const override
  {
    btConvexHullShape::getAabb(transform, min, max);
    const btVector3 reach(kHullPairReach, kHullPairReach, kHullPairReach);
    min -= reach;
    max += reach;
  }
};

std::unique_ptr<btConvexHullShape> hullShape(const std::vector<Eigen::Vector3d>& points, double margin)
{
  auto shape = std::make_unique<ReachingHull>();
  for (const Eigen::Vector3d& p : points)
  {
    shape->addPoint(btVector3(p.x(), p.y(), p.z()), false);
  }
  // The margin first: the cached local box is the points' plus the margin of the moment, and
  // getAabb adds the margin again. Set after, the box kept Bullet's default 0.04 m margin, so
  // every hull's box was 4 cm too wide on each side (a stud 1 cm over the table collided with it
  // by GJK each step).
  shape->setMargin(margin);
  shape->recalcLocalAabb();
  return shape;
}
}  // namespace

double enclosedVolume(const TriangleMesh& mesh)
{
  double volume = 0.0;
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    volume += mesh.corner(t, 0).dot(mesh.corner(t, 1).cross(mesh.corner(t, 2))) / 6.0;
  }
  return volume;
}

std::unique_ptr<CollisionShape> makeTriangleMeshShape(const TriangleMesh& mesh, double margin)
{
  auto result = std::make_unique<CollisionShape>();
  for (const Eigen::Vector3d& v : mesh.vertices())
  {
    result->vertices.insert(result->vertices.end(), {v.x(), v.y(), v.z()});
  }
  for (const Eigen::Vector3i& t : mesh.triangles())
  {
    result->indices.insert(result->indices.end(), {t[0], t[1], t[2]});
  }
  result->triangle_array =
      std::make_unique<btTriangleIndexVertexArray>(mesh.triangleCount(), result->indices.data(), 3 * sizeof(int),
                                                   mesh.vertexCount(), result->vertices.data(), 3 * sizeof(btScalar));
  auto shape = std::make_unique<btBvhTriangleMeshShape>(result->triangle_array.get(), true);
  shape->setMargin(margin);
  result->shape = shape.get();
  result->owned.push_back(std::move(shape));
  return result;
}

std::unique_ptr<CollisionShape> makeCollisionShape(const Geometry& geometry, const TriangleMesh& walk_mesh,
                                                   bool is_static, double margin)
{
  auto result = std::make_unique<CollisionShape>();
  switch (geometry.kind)
  {
    case GeometryKind::kBox:
    {
      const Eigen::Vector3d half = geometry.size / 2.0;
      auto shape = std::make_unique<btBoxShape>(btVector3(half.x(), half.y(), half.z()));
      shape->setMargin(std::min(margin, 0.25 * half.minCoeff()));
      result->shape = shape.get();
      result->owned.push_back(std::move(shape));
      return result;
    }
    case GeometryKind::kSphere:
    {
      auto shape = std::make_unique<btSphereShape>(geometry.radius);
      result->shape = shape.get();
      result->owned.push_back(std::move(shape));
      return result;
    }
    case GeometryKind::kCylinder:
    {
      auto shape = std::make_unique<btCylinderShapeZ>(btVector3(geometry.radius, geometry.radius, geometry.length / 2));
      shape->setMargin(std::min(margin, 0.25 * std::min(geometry.radius, geometry.length / 2)));
      result->shape = shape.get();
      result->owned.push_back(std::move(shape));
      return result;
    }
    case GeometryKind::kMesh:
      break;
  }
  const TriangleMesh& mesh = walk_mesh;
  if (is_static)
  {
    return makeTriangleMeshShape(mesh, margin);
  }
  std::vector<btScalar> coordinates;
  for (const Eigen::Vector3d& v : mesh.vertices())
  {
    coordinates.insert(coordinates.end(), {v.x(), v.y(), v.z()});
  }
  const MeshHealth& health = mesh.health();
  const bool closed = health.boundary_edges == 0 && health.non_manifold_edges == 0;
  const double volume = enclosedVolume(mesh);
  const double hull = hullVolume(coordinates);
  result->exact = false;
  const bool convex = !closed || volume >= 0.995 * hull;
  const ConvexDecomposition decomposition =
      convex ? ConvexDecomposition() : cachedConvexDecomposition(mesh, "'" + geometry.mesh_path + "'");
  if (convex || decomposition.hulls->empty())
  {
    result->exact = closed && convex;
    auto shape = hullShape(mesh.vertices(), margin);
    result->shape = shape.get();
    result->owned.push_back(std::move(shape));
    return result;
  }
  result->decomposition_source = decomposition.source;
  const HullSet& hulls = *decomposition.hulls;
  auto compound = std::make_unique<btCompoundShape>();
  for (const std::vector<Eigen::Vector3d>& points : hulls)
  {
    auto part = hullShape(points, margin);
    compound->addChildShape(btTransform::getIdentity(), part.get());
    result->owned.push_back(std::move(part));
  }
  result->convex_parts = static_cast<int>(hulls.size());
  result->shape = compound.get();
  result->owned.push_back(std::move(compound));
  return result;
}
}  // namespace god_finger::internal
