// Convex decomposition of a concave mesh for collision (the walk keeps the full mesh), made
// fast enough for scanned objects (50k-500k triangles) and computed once per machine:
//  1. a mesh above kDecompositionTriangles triangles is first reduced to that many by
//     quadric edge collapse (mesh_simplification.h); the collapse stops earlier if
//     meshoptimizer's error estimate would exceed kSimplificationTolerance times the bounding-box
//     diagonal. HACD's cost grows faster than linearly with the triangle count (measured on a
//     busy 2-core machine: 0.5 s at 1000 triangles, 1.0 s at 1500, 2.3 s at 2000; a user
//     measured 58 s at 20k), while simplifying 100k triangles takes 0.04 s. On a 100k-triangle
//     torus (R = 6 cm, r = 2 cm) 1500 triangles keep every input vertex within 0.82 mm of the
//     coarse surface (0.36 % of the diagonal; meshoptimizer's own estimate is 0.38 mm);
//  2. HACD (Bullet's Extras) decomposes it, with Bullet's ConvexDecompositionDemo settings;
//  3. the hulls are kept in memory for the process and on disk (hull_cache.h) keyed by the
//     mesh's content (its vertices and triangles after scaling and repair) and
//     kDecompositionVersion, so that a second run, or another scene using the same mesh, loads
//     them in milliseconds.
// A mesh made of convex pieces already (givenConvexPieces) is used as given: neither simplified,
// decomposed nor cached.
// A decomposition that will take long (a cache miss at or above 1000 triangles to decompose)
// says so first, in one line on stderr.
//
// The simplified mesh is only HACD's input: hull points are its vertices, so input vertices.
// Units: metres, in the mesh's own frame. Hull points are vertices of the (simplified) mesh
// and HACD's hull vertices: every hull has at least 4 points. Not real-time.
#pragma once

#include "god_finger/geometry/triangle_mesh.h"

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace god_finger
{
// Bump when anything that changes the hulls changes (settings below, HACD's parameters, the
// simplifier): older cache files are then simply not found.
constexpr int kDecompositionVersion = 1;
constexpr int kDecompositionTriangles = 1500;
constexpr double kSimplificationTolerance = 0.004;

using HullSet = std::vector<std::vector<Eigen::Vector3d>>;

// A decomposition the user made (V-HACD's hulls in one OBJ, a collision mesh of convex parts):
// a closed mesh of at least 2 connected components, each convex (no corner of a piece in front
// of any of its faces' planes by more than kGivenPieceTolerance times the mesh's bounding-box
// diagonal), at most kMaxGivenPieces of at most kMaxGivenPieceTriangles triangles each. Its
// pieces are the hulls, never decomposed again; none (nullopt) for any other mesh.
constexpr int kMaxGivenPieces = 512;
constexpr int kMaxGivenPieceTriangles = 4096;
constexpr double kGivenPieceTolerance = 1e-6;
std::optional<HullSet> givenConvexPieces(const TriangleMesh& mesh);

enum class DecompositionSource
{
  kComputed,      // simplified (if needed) and decomposed now
  kProcessCache,  // already computed in this process
  kDiskCache,     // read from the hull cache on disk
  kGiven,         // the mesh's own convex pieces (givenConvexPieces), used as given
};
const char* decompositionSourceName(DecompositionSource source);

struct ConvexDecomposition
{
  std::shared_ptr<const HullSet> hulls;
  DecompositionSource source = DecompositionSource::kComputed;
  int input_triangles = 0;
  int decomposed_triangles = 0;       // after simplification (0 when it came from a cache)
  double simplification_error = 0.0;  // (m), meshoptimizer's bound (0 when from a cache)
};

// 128 bits of hash of the mesh's vertices and triangles and kDecompositionVersion, as 32 hex
// digits: the decomposition's name in both caches.
std::string decompositionKey(const TriangleMesh& mesh);

// Simplify + HACD, no cache. `label` (a file name) and `note` only serve the progress line:
// "god_finger: decomposing LABEL: 100000 -> 1500 triangles (NOTE)".
ConvexDecomposition decomposeConcaveMesh(const TriangleMesh& mesh, const std::string& label,
                                         const std::string& note = "not cached");

// decomposeConcaveMesh through the process's cache and the disk cache (thread-safe).
ConvexDecomposition cachedConvexDecomposition(const TriangleMesh& mesh, const std::string& label);

// Forgets the process's cache (tests: to see the disk cache at work).
void clearProcessDecompositionCache();
}  // namespace god_finger
