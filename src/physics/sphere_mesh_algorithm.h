// A sphere against a BVH triangle mesh (btBvhTriangleMeshShape), the pair a finger (its proxy is
// a sphere) makes with a body's true surface (near_callback.h), a static mesh, or a ball with
// either. It replaces Bullet's convex-against-concave algorithm for that pair, which builds a
// triangle shape, a wrapper and a sphere-triangle algorithm (allocated and freed) for every
// triangle in the sphere's box: about 2,600 instructions per triangle, 35 % of a step with one
// finger on a fine mesh (bench/NOTES.md, issue 27). Here each triangle of the same BVH query
// costs one closest-point test.
//
// Same contacts as Bullet's: every triangle whose closest point to the sphere's centre lies
// within the radius plus the manifold's breaking threshold gives one point, on the triangle,
// with the normal from that point to the centre (the triangle's own normal, turned towards the
// centre, when the centre lies on it), depth = distance - radius; the persistent manifold merges
// and limits them as it does any algorithm's. Units: the world's (m). Frames: the mesh shape's
// (its wrapper's transform) for the query, world for the points.
//
// Registered on a dispatcher by registerSphereMeshAlgorithm, for contact points and closest
// points, both orders. Real-time safe once created (the dispatcher creates it from its pools on
// the pair's first overlap; the manifold likewise).
#pragma once

#include <btBulletCollisionCommon.h>

namespace god_finger::internal
{
// Replaces `dispatcher`'s algorithm for sphere / triangle-mesh pairs (either order). The create
// functions are static: registering on several dispatchers is fine.
void registerSphereMeshAlgorithm(btCollisionDispatcher* dispatcher);
}  // namespace god_finger::internal
