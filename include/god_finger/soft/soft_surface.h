// A soft body's boundary as a walk mesh (the triangle mesh a finger's contact area walks on and
// Bullet collides with), and the nodes that glue the body to what it rests on.
//
// Units: metres. Frames: the surface's vertices are in the body's frame (its volume file's);
// nodesGluedToSupport reads heights along world z (REP-103, up) after `body_in_world`.
// Invariants: the surface mesh's triangles are surfaceTriangles(mesh)'s (outward), its vertex v
// is node node_of_vertex[v] of the volume; every surface node is one vertex (none welded: a
// volume whose surface nodes coincide is refused). Not real-time: builds tables.
#pragma once

#include "god_finger/geometry/triangle_mesh.h"
#include "god_finger/soft/tet_mesh.h"

#include <Eigen/Geometry>
#include <vector>

namespace god_finger
{
struct SoftSurfaceMesh
{
  TriangleMesh mesh;
  std::vector<int> node_of_vertex;  // by mesh vertex: the volume's node
};

// The boundary of `volume` (checked: checkedTetMesh) as a TriangleMesh. InputError naming
// `source` when its surface does not make one mesh vertex per surface node.
SoftSurfaceMesh makeSoftSurfaceMesh(const TetMesh& volume, const std::string& source);

// The nodes a soft body resting on a support is glued by: those within
// max(kGlueMinBand, kGlueHeightFraction x its height) of its lowest point, heights along world z
// with the body's frame at `body_in_world`.
constexpr double kGlueHeightFraction = 0.02;
constexpr double kGlueMinBand = 1e-4;  // m
std::vector<int> nodesGluedToSupport(const TetMesh& volume, const Eigen::Isometry3d& body_in_world);
}  // namespace god_finger
