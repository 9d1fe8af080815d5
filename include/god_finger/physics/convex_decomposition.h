// Convex decomposition of a concave mesh for collision (the walk keeps the full mesh), made
// fast enough for scanned objects (50k-500k triangles) and computed once per machine:
//  1. a mesh above kSimplifyAbove triangles is first reduced to kDecompositionTriangles by
//     quadric edge collapse (mesh_simplification.h), never moving the surface by more than
//     kSimplificationTolerance (relative to the bounding-box diagonal; 0.4 %, i.e. 0.6 mm on a
//     16 cm object): HACD's cost grows faster than linearly (1 s at 2k triangles, 58 s at 20k);
//  2. HACD (Bullet's Extras) decomposes it, with Bullet's ConvexDecompositionDemo settings;
//  3. the hulls are kept in memory for the process and on disk (hull_cache.h) keyed by the
//     mesh's content (its vertices and triangles after scaling and repair) and
//     kDecompositionVersion, so that a second run, or another scene using the same mesh, loads
//     them in milliseconds.
// A decomposition that will take long (a cache miss at or above 1000 triangles to decompose)
// says so first, in one line on stderr.
//
// Units: metres, in the mesh's own frame. Hull points are vertices of the (simplified) mesh
// and HACD's hull vertices: every hull has at least 4 points. Not real-time.
#pragma once

#include "god_finger/core/triangle_mesh.h"

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace god_finger
{
// Bump when anything that changes the hulls changes (settings below, HACD's parameters, the
// simplifier): older cache files are then simply not found.
constexpr int kDecompositionVersion = 1;
constexpr int kSimplifyAbove = 2000;
constexpr int kDecompositionTriangles = 2000;
constexpr double kSimplificationTolerance = 0.004;

using HullSet = std::vector<std::vector<Eigen::Vector3d>>;

enum class DecompositionSource
{
  kComputed,      // simplified (if needed) and decomposed now
  kProcessCache,  // already computed in this process
  kDiskCache,     // read from the hull cache on disk
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

// Simplify + HACD, no cache. `label` (a file name) only serves the progress line.
ConvexDecomposition decomposeConcaveMesh(const TriangleMesh& mesh, const std::string& label);

// decomposeConcaveMesh through the process's cache and the disk cache (thread-safe).
ConvexDecomposition cachedConvexDecomposition(const TriangleMesh& mesh, const std::string& label);

// Forgets the process's cache (tests: to see the disk cache at work).
void clearProcessDecompositionCache();
}  // namespace god_finger
