#include "sphere_mesh_algorithm.h"

#include <BulletCollision/CollisionDispatch/btActivatingCollisionAlgorithm.h>

#include <new>

namespace god_finger::internal
{
namespace
{
// The point of triangle (a, b, c) closest to p, by the Voronoi region p lies in (vertex, edge or
// face; Ericson, Real-Time Collision Detection, 5.1.5).
btVector3 closestOnTriangle(const btVector3& p, const btVector3& a, const btVector3& b, const btVector3& c)
{
  const btVector3 ab = b - a;
  const btVector3 ac = c - a;
  const btVector3 ap = p - a;
  const btScalar d1 = ab.dot(ap);
  const btScalar d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0)
  {
    return a;
  }
  const btVector3 bp = p - b;
  const btScalar d3 = ab.dot(bp);
  const btScalar d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3)
  {
    return b;
  }
  const btScalar vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0)
  {
    return a + ab * (d1 / (d1 - d3));
  }
  const btVector3 cp = p - c;
  const btScalar d5 = ab.dot(cp);
  const btScalar d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6)
  {
    return c;
  }
  const btScalar vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0)
  {
    return a + ac * (d2 / (d2 - d6));
  }
  const btScalar va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
  {
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  const btScalar denominator = 1 / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

class SphereMeshAlgorithm : public btActivatingCollisionAlgorithm
{
 public:
  SphereMeshAlgorithm(const btCollisionAlgorithmConstructionInfo& info, const btCollisionObjectWrapper* first,
                      const btCollisionObjectWrapper* second, bool mesh_first)
      : btActivatingCollisionAlgorithm(info, first, second), mesh_first_(mesh_first)
  {
    const btCollisionObjectWrapper* sphere = mesh_first ? second : first;
    const btCollisionObjectWrapper* mesh = mesh_first ? first : second;
    manifold_ = m_dispatcher->getNewManifold(sphere->getCollisionObject(), mesh->getCollisionObject());
  }

  ~SphereMeshAlgorithm() override
  {
    m_dispatcher->releaseManifold(manifold_);
  }

  void processCollision(const btCollisionObjectWrapper* first, const btCollisionObjectWrapper* second,
                        const btDispatcherInfo& /*info*/, btManifoldResult* result) override
  {
    const btCollisionObjectWrapper* sphere_wrap = mesh_first_ ? second : first;
    const btCollisionObjectWrapper* mesh_wrap = mesh_first_ ? first : second;
    const auto* sphere = static_cast<const btSphereShape*>(sphere_wrap->getCollisionShape());
    const auto* mesh = static_cast<const btConcaveShape*>(mesh_wrap->getCollisionShape());
    result->setPersistentManifold(manifold_);

    Triangles triangles;
    triangles.result = result;
    triangles.mesh_object = mesh_wrap->getCollisionObject();
    triangles.mesh_transform = &mesh_wrap->getWorldTransform();
    triangles.centre = mesh_wrap->getWorldTransform().invXform(sphere_wrap->getWorldTransform().getOrigin());
    triangles.radius = sphere->getRadius();
    const btScalar reach =
        triangles.radius + manifold_->getContactBreakingThreshold() + result->m_closestPointDistanceThreshold;
    triangles.reach_squared = reach * reach;
    const btVector3 box(reach, reach, reach);
    mesh->processAllTriangles(&triangles, triangles.centre - box, triangles.centre + box);
    result->refreshContactPoints();
  }

  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override
  {
    return 1;  // no continuous collision: as Bullet's sphere-triangle algorithm
  }

  void getAllContactManifolds(btManifoldArray& manifolds) override
  {
    manifolds.push_back(manifold_);
  }

  struct CreateFunc : btCollisionAlgorithmCreateFunc
  {
    explicit CreateFunc(bool mesh_first)
    {
      m_swapped = mesh_first;
    }
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& info,
                                                   const btCollisionObjectWrapper* first,
                                                   const btCollisionObjectWrapper* second) override
    {
      void* memory = info.m_dispatcher1->allocateCollisionAlgorithm(sizeof(SphereMeshAlgorithm));
      return new (memory) SphereMeshAlgorithm(info, first, second, m_swapped);
    }
  };

 private:
  // Each triangle of the BVH query: one contact point where the sphere comes within reach.
  struct Triangles : btTriangleCallback
  {
    btManifoldResult* result = nullptr;
    const btCollisionObject* mesh_object = nullptr;
    const btTransform* mesh_transform = nullptr;
    btVector3 centre;  // the sphere's, in the mesh's frame
    btScalar radius = 0;
    btScalar reach_squared = 0;

    void processTriangle(btVector3* corners, int part, int index) override
    {
      const btVector3 face_normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
      const btScalar face_length_squared = face_normal.length2();
      if (face_length_squared < SIMD_EPSILON * SIMD_EPSILON)
      {
        return;  // a degenerate triangle has no side to touch
      }
      const btVector3 closest = closestOnTriangle(centre, corners[0], corners[1], corners[2]);
      const btVector3 offset = centre - closest;
      const btScalar distance_squared = offset.length2();
      if (distance_squared >= reach_squared)
      {
        return;
      }
      btVector3 normal;  // from the triangle to the centre, in the mesh's frame
      btScalar distance = 0;
      if (distance_squared > SIMD_EPSILON)
      {
        distance = btSqrt(distance_squared);
        normal = offset / distance;
      }
      else
      {
        // The centre on the triangle: its normal, on the side the centre is (to rounding).
        normal = face_normal / btSqrt(face_length_squared);
        normal = normal.dot(centre - corners[0]) < 0 ? -normal : normal;
      }
      if (result->getBody0Internal() == mesh_object)
      {
        result->setShapeIdentifiersA(part, index);
      }
      else
      {
        result->setShapeIdentifiersB(part, index);
      }
      // In the manifold's order (sphere, mesh), whichever order the result's bodies are in:
      // btManifoldResult finds each body's frame by the manifold's order (as Bullet's own
      // per-triangle algorithm relies on).
      result->addContactPoint(mesh_transform->getBasis() * normal, (*mesh_transform) * closest, distance - radius);
    }
  };

  btPersistentManifold* manifold_ = nullptr;
  bool mesh_first_;
};
}  // namespace

void registerSphereMeshAlgorithm(btCollisionDispatcher* dispatcher)
{
  static SphereMeshAlgorithm::CreateFunc sphere_first(false);
  static SphereMeshAlgorithm::CreateFunc mesh_first(true);
  dispatcher->registerCollisionCreateFunc(SPHERE_SHAPE_PROXYTYPE, TRIANGLE_MESH_SHAPE_PROXYTYPE, &sphere_first);
  dispatcher->registerCollisionCreateFunc(TRIANGLE_MESH_SHAPE_PROXYTYPE, SPHERE_SHAPE_PROXYTYPE, &mesh_first);
  dispatcher->registerClosestPointsCreateFunc(SPHERE_SHAPE_PROXYTYPE, TRIANGLE_MESH_SHAPE_PROXYTYPE, &sphere_first);
  dispatcher->registerClosestPointsCreateFunc(TRIANGLE_MESH_SHAPE_PROXYTYPE, SPHERE_SHAPE_PROXYTYPE, &mesh_first);
}
}  // namespace god_finger::internal
