// A mesh as a file stores it: vertex positions and faces of any number of corners, before
// triangulation. The own readers (PLY, OFF) and the assimp path all produce one, and
// appendTriangulated() turns it into triangles in one place.
//
// Units: the file's (taken as metres). Not real-time: everything here allocates.
#pragma once

#include "god_finger/geometry/triangle_mesh.h"

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace god_finger
{
struct PolygonSoup
{
  std::vector<Eigen::Vector3d> vertices;
  // Face f's corners are corners[face_starts[f]] .. corners[face_starts[f + 1] - 1]; indices
  // into `vertices`, not yet checked (a file may hold anything). face_starts has faces + 1 entries.
  std::vector<long long> corners;
  std::vector<std::size_t> face_starts{0};

  int faceCount() const
  {
    return static_cast<int>(face_starts.size()) - 1;
  }
  void endFace()
  {
    face_starts.push_back(corners.size());
  }
};

// Called by the readers with a file's declared vertex and face counts as soon as they are known,
// before anything is allocated for them: the place to refuse a file too large for the machine
// (support/memory_budget.h) by throwing.
using DeclaredSizeCheck = std::function<void(std::uint64_t vertices, std::uint64_t faces)>;

// The most corners one face may have: ear clipping is quadratic or worse in them, and no
// modelling tool writes more in one face.
constexpr int kMaxFaceCorners = 4096;

// Appends `polygons` to `soup` (vertices after those already there), each face ear-clipped on
// its best-fit plane (geometry/polygon_triangulation.h); faces of fewer than 3 corners (points,
// lines) are skipped. Throws InputError ("face F refers to vertex V of N", "face F has K
// corners, more than 4096", or the triangulation's reason for face F) and leaves `soup` as it was.
// The soup's triangles index its vertices with int: more than `max_vertices` (INT_MAX; smaller
// only in tests) vertices in all is refused the same way, naming the count.
void appendTriangulated(const PolygonSoup& polygons, TriangleSoup* soup,
                        long long max_vertices = std::numeric_limits<int>::max());
}  // namespace god_finger
