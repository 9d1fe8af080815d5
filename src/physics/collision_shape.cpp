#include "collision_shape.h"

#include <BulletCollision/CollisionShapes/btShapeHull.h>
#include <HACD/hacdHACD.h>
#include <LinearMath/btConvexHullComputer.h>

#include <map>
#include <mutex>
#include <sstream>

namespace god_finger
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

using HullSet = std::vector<std::vector<btVector3>>;

// HACD decomposition of a closed concave mesh into convex hulls' points.
HullSet decompose(const TriangleMesh& mesh)
{
  std::vector<HACD::Vec3<HACD::Real>> points;
  std::vector<HACD::Vec3<long>> triangles;
  points.reserve(mesh.vertexCount());
  for (const Eigen::Vector3d& v : mesh.vertices())
  {
    points.emplace_back(v.x(), v.y(), v.z());
  }
  for (const Eigen::Vector3i& t : mesh.triangles())
  {
    triangles.emplace_back(t[0], t[1], t[2]);
  }
  HACD::HACD hacd;
  hacd.SetPoints(points.data());
  hacd.SetNPoints(points.size());
  hacd.SetTriangles(triangles.data());
  hacd.SetNTriangles(triangles.size());
  // Bullet's ConvexDecompositionDemo settings: concavity in HACD's normalised units.
  hacd.SetCompacityWeight(0.1);
  hacd.SetVolumeWeight(0.0);
  hacd.SetNClusters(2);
  hacd.SetNVerticesPerCH(100);
  hacd.SetConcavity(100);
  hacd.SetAddExtraDistPoints(false);
  hacd.SetAddNeighboursDistPoints(false);
  hacd.SetAddFacesPoints(false);
  hacd.Compute();
  HullSet hulls;
  for (std::size_t c = 0; c < hacd.GetNClusters(); ++c)
  {
    std::vector<HACD::Vec3<HACD::Real>> hull_points(hacd.GetNPointsCH(c));
    std::vector<HACD::Vec3<long>> hull_triangles(hacd.GetNTrianglesCH(c));
    hacd.GetCH(c, hull_points.data(), hull_triangles.data());
    std::vector<btVector3> hull;
    for (const auto& p : hull_points)
    {
      hull.emplace_back(p.X(), p.Y(), p.Z());
    }
    if (hull.size() >= 4)
    {
      hulls.push_back(hull);
    }
  }
  return hulls;
}

const HullSet& cachedDecomposition(const Geometry& geometry, const TriangleMesh& mesh)
{
  static std::mutex mutex;
  static std::map<std::string, HullSet> cache;
  std::ostringstream key;
  key.precision(17);
  key << geometry.mesh_path << '|' << geometry.scale.transpose();
  std::lock_guard<std::mutex> lock(mutex);
  auto found = cache.find(key.str());
  if (found == cache.end())
  {
    found = cache.emplace(key.str(), decompose(mesh)).first;
  }
  return found->second;
}

std::unique_ptr<btConvexHullShape> hullShape(const std::vector<btVector3>& points, double margin)
{
  auto shape = std::make_unique<btConvexHullShape>();
  for (const btVector3& p : points)
  {
    shape->addPoint(p, false);
  }
  shape->recalcLocalAabb();
  shape->setMargin(margin);
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

std::unique_ptr<CollisionShape> makeCollisionShape(const Geometry& geometry, const TriangleMesh& walk_surface,
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
  const TriangleMesh& mesh = walk_surface;
  if (is_static)
  {
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
  if (!closed || volume >= 0.995 * hull)
  {
    std::vector<btVector3> points;
    for (const Eigen::Vector3d& v : mesh.vertices())
    {
      points.emplace_back(v.x(), v.y(), v.z());
    }
    result->exact = closed;
    auto shape = hullShape(points, margin);
    result->shape = shape.get();
    result->owned.push_back(std::move(shape));
    return result;
  }
  const HullSet& hulls = cachedDecomposition(geometry, mesh);
  auto compound = std::make_unique<btCompoundShape>();
  for (const std::vector<btVector3>& points : hulls)
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
}  // namespace god_finger
