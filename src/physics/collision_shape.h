// Bullet collision shapes for scene geometry. Primitives collide as Bullet's primitives. A
// mesh collides as: its own triangles (btBvhTriangleMeshShape) when the body is static; its
// convex hull when it is convex (hull volume within 0.5 % of the mesh's); otherwise a convex
// decomposition (convex_decomposition.h: simplified first when large, HACD, cached in the
// process and on disk by content). The walk mesh stays the original mesh in every case.
//
// Margins: Bullet rounds convex shapes by a collision margin (default 4 cm, far too large for
// a finger on a 5 cm object): every shape gets `margin` (m), primitives keep their true size.
#pragma once

#include "god_finger/geometry/triangle_mesh.h"
#include "god_finger/scene/convex_decomposition.h"
#include "god_finger/scene/scene_description.h"

#include <btBulletCollisionCommon.h>

#include <memory>
#include <vector>

namespace god_finger::internal
{
// A convex hull's box reaches kHullPairReach beyond its points and margin: another body's
// piece pairs with it (Bullet's compound algorithms test the pieces' boxes) before the two
// touch, so their first contact comes a step ahead, as a speculative one, instead of a step late
// and already 1 mm deep. A mug dropped at 1.35 m/s onto the table (hand_grasp with the fake
// hand) sinks 0.21 mm with it and 1.21 mm without; with the box 4 cm too wide (the margin set
// after the box was cached) every piece within 4 cm paired, and GJK ran for a brick's studs 1 cm
// over the table each step.
constexpr double kHullPairReach = 0.002;  // m: ~3 m/s of approach in a 1 ms step, with the margins

struct CollisionShape
{
  btCollisionShape* shape = nullptr;  // the top shape (owned through `owned`)
  int convex_parts = 1;               // hulls in a decomposition, 1 otherwise
  bool exact = true;                  // false when collision uses a hull or a decomposition
  // Where a decomposition's hulls came from (kComputed when there is none).
  DecompositionSource decomposition_source = DecompositionSource::kComputed;
  std::vector<std::unique_ptr<btCollisionShape>> owned;
  std::unique_ptr<btTriangleIndexVertexArray> triangle_array;
  std::vector<int> indices;
  std::vector<btScalar> vertices;
};

std::unique_ptr<CollisionShape> makeCollisionShape(const Geometry& geometry, const TriangleMesh& walk_mesh,
                                                   bool is_static, double margin = 0.0005);

// `mesh`'s own triangles as a btBvhTriangleMeshShape (exact; a static mesh's collision shape,
// and the surface fingers touch on a body that collides through hulls: scene_body.h).
std::unique_ptr<CollisionShape> makeTriangleMeshShape(const TriangleMesh& mesh, double margin = 0.0005);

// Volume enclosed by a closed mesh (m^3); meaningless for open meshes.
double enclosedVolume(const TriangleMesh& mesh);
}  // namespace god_finger::internal
