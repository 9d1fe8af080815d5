#include "god_finger/geometry/surface_locator.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace god_finger
{
namespace
{
// Depth bound of the traversal stack: a median split halves the range at every level, so
// depth <= log2(n / kLeafSize) + 1 (about 30 for 2^31 triangles).
constexpr int kMaxStack = 128;

double squaredDistanceToBox(const Eigen::Vector3d& p, const Eigen::Vector3d& lower, const Eigen::Vector3d& upper)
{
  const Eigen::Vector3d below = (lower - p).cwiseMax(0.0);
  const Eigen::Vector3d above = (p - upper).cwiseMax(0.0);
  return (below + above).squaredNorm();
}
}  // namespace

SurfaceLocator::SurfaceLocator(const TriangleMesh& mesh) : mesh_(&mesh)
{
  const int n = mesh.triangleCount();
  order_.resize(n);
  std::iota(order_.begin(), order_.end(), 0);
  std::vector<Eigen::Vector3d> centroids(n);
  for (int t = 0; t < n; ++t)
  {
    centroids[t] = (mesh.corner(t, 0) + mesh.corner(t, 1) + mesh.corner(t, 2)) / 3.0;
  }
  nodes_.reserve(2 * (n / kLeafSize + 1));
  nodes_.push_back(Node());
  buildNode(0, 0, n, centroids, 1);
  nodes_.shrink_to_fit();
}

void SurfaceLocator::buildNode(int index, int begin, int end, const std::vector<Eigen::Vector3d>& centroids, int level)
{
  depth_ = std::max(depth_, level);
  Eigen::Vector3d lower = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d upper = -lower;
  Eigen::Vector3d centroid_lower = lower;
  Eigen::Vector3d centroid_upper = upper;
  for (int i = begin; i < end; ++i)
  {
    const int t = order_[i];
    for (int j = 0; j < 3; ++j)
    {
      lower = lower.cwiseMin(mesh_->corner(t, j));
      upper = upper.cwiseMax(mesh_->corner(t, j));
    }
    centroid_lower = centroid_lower.cwiseMin(centroids[t]);
    centroid_upper = centroid_upper.cwiseMax(centroids[t]);
  }
  nodes_[index].lower = lower;
  nodes_[index].upper = upper;
  if (end - begin <= kLeafSize)
  {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return;
  }
  int axis = 0;
  (centroid_upper - centroid_lower).maxCoeff(&axis);
  const int middle = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                   [&](int a, int b) { return centroids[a][axis] < centroids[b][axis]; });
  const int left = static_cast<int>(nodes_.size());
  nodes_.push_back(Node());
  nodes_.push_back(Node());
  nodes_[index].first = left;
  nodes_[index].count = 0;
  buildNode(left, begin, middle, centroids, level + 1);
  buildNode(left + 1, middle, end, centroids, level + 1);
}

void SurfaceLocator::refit()
{
  // Children come after their parent (buildNode appends them): a reverse sweep is bottom-up.
  for (int index = static_cast<int>(nodes_.size()) - 1; index >= 0; --index)
  {
    Node& node = nodes_[index];
    if (node.count > 0)
    {
      node.lower = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
      node.upper = -node.lower;
      for (int i = node.first; i < node.first + node.count; ++i)
      {
        for (int j = 0; j < 3; ++j)
        {
          node.lower = node.lower.cwiseMin(mesh_->corner(order_[i], j));
          node.upper = node.upper.cwiseMax(mesh_->corner(order_[i], j));
        }
      }
    }
    else
    {
      node.lower = nodes_[node.first].lower.cwiseMin(nodes_[node.first + 1].lower);
      node.upper = nodes_[node.first].upper.cwiseMax(nodes_[node.first + 1].upper);
    }
  }
}

SurfaceLocation SurfaceLocator::closest(const Eigen::Vector3d& query, double feature_tolerance) const
{
  int stack[kMaxStack];
  int top = 0;
  stack[top++] = 0;
  double best_squared = std::numeric_limits<double>::infinity();
  SurfaceLocation best;
  while (top > 0)
  {
    const Node& node = nodes_[stack[--top]];
    if (squaredDistanceToBox(query, node.lower, node.upper) > best_squared)
    {
      continue;
    }
    if (node.count > 0)
    {
      for (int i = node.first; i < node.first + node.count; ++i)
      {
        const int face = order_[i];
        SurfaceLocation candidate = locateOnFace(*mesh_, face, query, feature_tolerance);
        const double squared = candidate.distance * candidate.distance;
        if (squared < best_squared || (squared == best_squared && face < best.face))
        {
          best_squared = squared;
          best = candidate;
        }
      }
      continue;
    }
    // Visit the nearer child first (pushed last) so that the bound tightens early.
    const int left = node.first;
    const int right = node.first + 1;
    const double left_distance = squaredDistanceToBox(query, nodes_[left].lower, nodes_[left].upper);
    const double right_distance = squaredDistanceToBox(query, nodes_[right].lower, nodes_[right].upper);
    if (top + 2 > kMaxStack)
    {
      continue;  // unreachable for any mesh that fits in memory (see kMaxStack)
    }
    if (left_distance <= right_distance)
    {
      stack[top++] = right;
      stack[top++] = left;
    }
    else
    {
      stack[top++] = left;
      stack[top++] = right;
    }
  }
  return best;
}

std::size_t SurfaceLocator::memoryBytes() const
{
  return nodes_.capacity() * sizeof(Node) + order_.capacity() * sizeof(int) + sizeof(*this);
}
}  // namespace god_finger
