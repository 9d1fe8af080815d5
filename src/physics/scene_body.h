// A scene body as the world keeps it: its walk mesh (with its locator, or the exact surface
// of a sphere or cylinder), its collision shape, its Bullet rigid body and the frames between
// them. Internal to physics.
//
// Frames: the link frame (the scene's), the centre of mass frame on the principal axes of
// inertia (Bullet's body frame) and the geometry frame (the walk mesh's and the collision
// shape's). Units: SI. Not real-time safe to build; reading it is.
#pragma once

#include "collision_shape.h"
#include "soft_body.h"

#include "god_finger/contact/primitive_walk.h"
#include "god_finger/geometry/surface_locator.h"
#include "god_finger/geometry/triangle_mesh.h"
#include "god_finger/scene/scene_description.h"

#include <btBulletDynamicsCommon.h>

#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <vector>

namespace god_finger::internal
{
// The surface the fingers collide with when it is not the body's collision shape: a hull or a
// decomposition fills a hollow (a cup's, a plate's) and a visual mesh is the true surface, so a
// finger touches the walk mesh itself, a BVH of its triangles placed in the body frame; so does
// a free convex body (near_callback.h), while supports and other hollow bodies touch the
// collision shape. The body's btCollisionObject user
// pointer points to it (null when the collision shape is the walk surface: primitives, static
// meshes, convex closed meshes). Read by the world's near callback, real-time safe.
struct FingerSurface
{
  std::unique_ptr<CollisionShape> mesh;
  btTransform in_body = btTransform::getIdentity();  // the walk mesh's frame in Bullet's body frame
};

// A body's collision shapes placed in its centre-of-mass frame (Bullet's compound), whose box
// also covers the body's FingerSurface: a visual mesh reaching beyond the collision shapes (a
// scanned surface over small hulls) is within the broadphase's reach of the fingers. Collision
// between the pieces is the compound's own; only the box grows.
class PlacedShape : public btCompoundShape
{
 public:
  // `extra_min`, `extra_max`: a box in the centre-of-mass frame to cover too (the finger surface's).
  void coverToo(const btVector3& extra_min, const btVector3& extra_max);
  void getAabb(const btTransform& transform, btVector3& min, btVector3& max) const override;

 private:
  bool extra_ = false;
  btVector3 extra_min_ = btVector3(0, 0, 0);
  btVector3 extra_max_ = btVector3(0, 0, 0);
};

struct SceneBody
{
  std::unique_ptr<TriangleMesh> walk;
  std::unique_ptr<SurfaceLocator> locator;
  // Spheres and cylinders: contact areas by exact walks (contact/primitive_walk.h); the walk
  // surface then only serves the collision shape and walkMesh().
  std::optional<PrimitiveSurface> primitive;
  std::unique_ptr<CollisionShape> collision;
  // A compound body's other pieces (BodyDescription::more_parts): their shapes, each at its
  // place in the geometry frame (the first piece's).
  std::vector<std::unique_ptr<CollisionShape>> part_collisions;
  std::vector<Eigen::Isometry3d> part_in_geometry;
  std::unique_ptr<FingerSurface> finger_surface;  // null where the fingers touch `placed`
  std::unique_ptr<PlacedShape> placed;            // the collision shape(s) placed in the centre-of-mass frame
  std::unique_ptr<btRigidBody> rigid;
  Eigen::Isometry3d com_in_link = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d geometry_in_com = Eigen::Isometry3d::Identity();
  btVector3 principal_inertia = btVector3(0, 0, 0);
  Eigen::Vector3d previous_velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d net_force = Eigen::Vector3d::Zero();
  // A soft body's volume (soft_body.h; null otherwise, and until the world makes it).
  std::unique_ptr<SoftVolume> soft;
  int left_world = 0;           // BodyState::left_world (kept across resets)
  double left_world_at = -1.0;  // s, world time
};

// The walk mesh (a primitive's tessellated with edges of at most `max_edge` m; a compound's,
// the union of its pieces' in the first piece's frame), locator, exact surface (one sphere or
// cylinder only), collision shape(s) and frames of `description`; no rigid body yet.
SceneBody makeSceneBody(const BodyDescription& description, double max_edge);

// (Re)builds `body`'s placed shape and rigid body (scene index `index`, tagged kKindBody) at
// its description's pose, with its mass, inertia and material; the caller adds it to the world.
void buildRigidBody(const BodyDescription& description, int index, SceneBody* body);
}  // namespace god_finger::internal
