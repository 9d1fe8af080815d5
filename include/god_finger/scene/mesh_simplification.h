// Reduces a triangle mesh to a coarse one for collision only (the walk keeps the full mesh):
// quadric edge collapse by meshoptimizer (Debian's libmeshoptimizer, meshopt_simplify), which
// keeps the topology (a torus stays a torus) and reports the error it introduced.
//
// Units: metres, in the mesh's own frame. Invariants of the result: at most
// max(target_triangles, what the error bound forces) triangles, every vertex an input vertex
// (collapse never moves vertices, so no point leaves the input's convex hull), and
// `error` = meshoptimizer's bound on the distance between the two surfaces (its quadric error,
// in metres); the collapse stops before `error` would exceed `max_error`. Not real-time.
#pragma once

#include "god_finger/geometry/triangle_mesh.h"

namespace god_finger
{
struct SimplifiedMesh
{
  TriangleSoup soup;   // compacted: only the vertices the kept triangles use
  double error = 0.0;  // (m), see the header comment
};

// The mesh unchanged (error 0) when it has at most `target_triangles` triangles.
SimplifiedMesh simplifyMesh(const TriangleMesh& mesh, int target_triangles, double max_error);
}  // namespace god_finger
