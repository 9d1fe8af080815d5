// Closest-point queries on a triangle mesh through a bounding-volume hierarchy, so that the
// cost grows like log(n) with the triangle count.
//
// Why our own tree: Eigen's KdBVH/BVMinimize allocates a priority queue on every query, and
// this query runs inside the 1 kHz loop; this one uses a fixed stack and never allocates
// after construction. Bullet's trees are not available to `core` (Eigen only).
//
// Invariants: built once from a mesh that must outlive the locator (refit() after it deforms); leaves hold at most
// kLeafSize triangles; node boxes enclose their triangles exactly (double precision).
#pragma once

#include "god_finger/geometry/surface_location.h"

#include <cstddef>
#include <vector>

namespace god_finger
{
class SurfaceLocator
{
 public:
  static constexpr int kLeafSize = 4;

  explicit SurfaceLocator(const TriangleMesh& mesh);

  // Closest point of the whole mesh to `query`. Ties go to the lowest triangle index met
  // first. Never allocates.
  SurfaceLocation closest(const Eigen::Vector3d& query, double feature_tolerance = kDefaultFeatureTolerance) const;

  // The boxes again after the mesh's vertices moved (TriangleMesh::moveVertices: same
  // triangles): O(n), the tree's shape kept (a deformed soft body's surface, each step). A tree
  // refitted after large motion stays correct, only slower to search. Never allocates.
  void refit();

  const TriangleMesh& mesh() const
  {
    return *mesh_;
  }
  // Bytes held by the tree (nodes and triangle order), not counting the mesh.
  std::size_t memoryBytes() const;
  int depth() const
  {
    return depth_;
  }

 private:
  struct Node
  {
    Eigen::Vector3d lower;
    Eigen::Vector3d upper;
    int first;  // internal: index of the left child (right = first + 1); leaf: first entry in order_
    int count;  // 0 for internal nodes
  };
  void buildNode(int index, int begin, int end, const std::vector<Eigen::Vector3d>& centroids, int level);

  const TriangleMesh* mesh_;
  std::vector<Node> nodes_;
  std::vector<int> order_;
  int depth_ = 0;
};
}  // namespace god_finger
