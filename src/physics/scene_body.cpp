#include "scene_body.h"

#include "bullet_helpers.h"

#include "god_finger/scene/walk_mesh.h"

#include <Eigen/Eigenvalues>

namespace god_finger::internal
{
namespace
{
// The exact walk's surface for a sphere or a cylinder; none for boxes (their 12-triangle walk
// surface is exact already) and meshes.
std::optional<PrimitiveSurface> primitiveSurface(const Geometry& geometry)
{
  if (geometry.kind == GeometryKind::kSphere)
  {
    return PrimitiveSurface{PrimitiveSurface::Kind::kSphere, geometry.radius, 0.0};
  }
  if (geometry.kind == GeometryKind::kCylinder)
  {
    return PrimitiveSurface{PrimitiveSurface::Kind::kCylinder, geometry.radius, geometry.length};
  }
  return std::nullopt;
}

// `more`'s triangles added to `soup`'s.
void append(const TriangleSoup& more, TriangleSoup* soup)
{
  const int offset = static_cast<int>(soup->vertices.size());
  soup->vertices.insert(soup->vertices.end(), more.vertices.begin(), more.vertices.end());
  for (const std::array<int, 3>& triangle : more.triangles)
  {
    soup->triangles.push_back({triangle[0] + offset, triangle[1] + offset, triangle[2] + offset});
  }
}

// `mesh`'s triangles moved by `place`, as a soup to build a union from.
TriangleSoup soupOf(const TriangleMesh& mesh, const Eigen::Isometry3d& place)
{
  TriangleSoup soup;
  for (const Eigen::Vector3d& vertex : mesh.vertices())
  {
    soup.vertices.push_back(place * vertex);
  }
  for (const Eigen::Vector3i& triangle : mesh.triangles())
  {
    soup.triangles.push_back({triangle[0], triangle[1], triangle[2]});
  }
  return soup;
}
}  // namespace

SceneBody makeSceneBody(const BodyDescription& description, double max_edge)
{
  SceneBody body;
  if (description.soft)
  {
    // A soft body: static, its surface its walk mesh and its own Bullet triangle mesh, both moved
    // as it deforms (soft_body.h; the world makes its volume).
    body.soft = std::make_unique<SoftVolume>();
    body.walk = makeSoftWalkMesh(description, &body.soft->node_of_vertex);
    body.locator = std::make_unique<SurfaceLocator>(*body.walk);
    body.collision = makeTriangleMeshShape(*body.walk);
    body.geometry_in_com = description.collision_origin;
    return body;
  }
  const TriangleMesh first = makeWalkMesh(description.geometry, max_edge);
  body.collision = makeCollisionShape(description.geometry, first, description.is_static);
  TriangleSoup pieces = soupOf(first, Eigen::Isometry3d::Identity());  // a compound's surfaces, united
  for (const BodyPart& part : description.more_parts)
  {
    const TriangleMesh part_walk = makeWalkMesh(part.geometry, max_edge);
    const Eigen::Isometry3d in_geometry = description.collision_origin.inverse() * part.origin;
    body.part_collisions.push_back(makeCollisionShape(part.geometry, part_walk, description.is_static));
    body.part_in_geometry.push_back(in_geometry);
    append(soupOf(part_walk, in_geometry), &pieces);
  }
  if (description.visual_mesh)
  {
    // The true surface: the pad walks on the visual mesh (in the first piece's frame), whatever
    // the collision pieces are.
    const TriangleMesh visual = makeWalkMesh(description.visual_mesh->geometry, max_edge);
    body.walk = std::make_unique<TriangleMesh>(
        TriangleMesh::build(soupOf(visual, description.collision_origin.inverse() * description.visual_mesh->origin)));
  }
  else if (description.more_parts.empty())
  {
    body.walk = std::make_unique<TriangleMesh>(first);
    body.primitive = primitiveSurface(description.geometry);
  }
  else
  {
    // A compound: the pad walks on the union of its pieces' surfaces (no exact primitive walk).
    body.walk = std::make_unique<TriangleMesh>(TriangleMesh::build(pieces));
  }
  body.locator = std::make_unique<SurfaceLocator>(*body.walk);
  bool exact = body.collision->exact;
  for (const std::unique_ptr<CollisionShape>& part : body.part_collisions)
  {
    exact = exact && part->exact;
  }
  if (!exact || description.visual_mesh)
  {
    body.finger_surface = std::make_unique<FingerSurface>();
    body.finger_surface->mesh = makeTriangleMeshShape(*body.walk);
  }
  if (!description.is_static)
  {
    // Bullet's body frame is the centre of mass on the principal axes of inertia.
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(description.inertia);
    Eigen::Matrix3d axes = solver.eigenvectors();
    if (axes.determinant() < 0.0)
    {
      axes.col(2) = -axes.col(2);
    }
    body.com_in_link = description.inertial_origin;
    body.com_in_link.linear() = description.inertial_origin.linear() * axes;
    const Eigen::Vector3d moments = solver.eigenvalues();
    body.principal_inertia = toBullet(moments);
  }
  body.geometry_in_com = body.com_in_link.inverse() * description.collision_origin;
  return body;
}

void PlacedShape::coverToo(const btVector3& extra_min, const btVector3& extra_max)
{
  extra_ = true;
  extra_min_ = extra_min;
  extra_max_ = extra_max;
}

void PlacedShape::getAabb(const btTransform& transform, btVector3& min, btVector3& max) const
{
  btCompoundShape::getAabb(transform, min, max);
  if (extra_)
  {
    btVector3 extra_min;
    btVector3 extra_max;
    btTransformAabb(extra_min_, extra_max_, 0.0, transform, extra_min, extra_max);
    min.setMin(extra_min);
    max.setMax(extra_max);
  }
}

void buildRigidBody(const BodyDescription& description, int index, SceneBody* body)
{
  body->placed = std::make_unique<PlacedShape>();
  body->placed->addChildShape(toBullet(body->geometry_in_com), body->collision->shape);
  for (std::size_t i = 0; i < body->part_collisions.size(); ++i)
  {
    body->placed->addChildShape(toBullet(body->geometry_in_com * body->part_in_geometry[i]),
                                body->part_collisions[i]->shape);
  }
  const double mass = description.is_static ? 0.0 : description.mass;
  btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, body->placed.get(),
                                                description.is_static ? btVector3(0, 0, 0) : body->principal_inertia);
  info.m_startWorldTransform = toBullet(description.pose * body->com_in_link);
  info.m_friction = description.material.friction;
  info.m_rollingFriction = description.material.rolling_friction;
  info.m_spinningFriction = description.material.spinning_friction;
  info.m_restitution = description.material.restitution;
  body->rigid = std::make_unique<btRigidBody>(info);
  body->rigid->setUserIndex(kKindBody);
  body->rigid->setUserIndex2(index);
  if (body->finger_surface)
  {
    body->finger_surface->in_body = toBullet(body->geometry_in_com);
    body->rigid->setUserPointer(body->finger_surface.get());
    btVector3 min;
    btVector3 max;
    body->finger_surface->mesh->shape->getAabb(body->finger_surface->in_body, min, max);
    body->placed->coverToo(min, max);
  }
}
}  // namespace god_finger::internal
