#include "god_finger/geometry/polygon_triangulation.h"

#include <Eigen/Geometry>
#include <cmath>

namespace god_finger
{
namespace
{
double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
  return a.x() * b.y() - a.y() * b.x();
}

// Inside or on the border of the counter-clockwise triangle (a, b, c), with tolerance `eps`.
bool inTriangle(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                double eps)
{
  return cross2(b - a, p - a) >= -eps && cross2(c - b, p - b) >= -eps && cross2(a - c, p - c) >= -eps;
}
}  // namespace

std::string triangulatePolygon(const std::vector<Eigen::Vector3d>& corners, std::vector<std::array<int, 3>>* triangles)
{
  triangles->clear();
  // Corners without consecutive repeats (nor a last one equal to the first).
  std::vector<int> ring;
  for (int i = 0; i < static_cast<int>(corners.size()); ++i)
  {
    if (ring.empty() || corners[i] != corners[ring.back()])
    {
      ring.push_back(i);
    }
  }
  while (ring.size() > 1 && corners[ring.front()] == corners[ring.back()])
  {
    ring.pop_back();
  }
  if (ring.size() < 3)
  {
    return "";
  }
  // Newell's normal: twice the vector area; its length is twice the (projected) area.
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < ring.size(); ++i)
  {
    normal += corners[ring[i]].cross(corners[ring[(i + 1) % ring.size()]]);
  }
  double scale = 0.0;
  for (int i : ring)
  {
    scale = std::max(scale, (corners[i] - corners[ring[0]]).norm());
  }
  const double area2 = normal.norm();
  if (!(area2 > 1e-12 * scale * scale))
  {
    // No net area: all corners on one line (nothing to triangulate), or lobes that turn both
    // ways and cancel (a bow tie: it crosses itself).
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();
    for (int i : ring)
    {
      if ((corners[i] - corners[ring[0]]).norm() > direction.norm())
      {
        direction = corners[i] - corners[ring[0]];
      }
    }
    for (int i : ring)
    {
      if ((corners[i] - corners[ring[0]]).cross(direction).norm() > 1e-9 * scale * scale)
      {
        return "polygon of " + std::to_string(corners.size()) + " corners crosses itself and cannot be triangulated";
      }
    }
    return "";
  }
  normal /= area2;
  const Eigen::Vector3d u = normal.unitOrthogonal();
  const Eigen::Vector3d v = normal.cross(u);
  std::vector<Eigen::Vector2d> points(corners.size());
  for (int i : ring)
  {
    points[i] = Eigen::Vector2d(corners[i].dot(u), corners[i].dot(v));  // counter-clockwise about `normal`
  }
  const double eps = 1e-12 * scale * scale;
  std::vector<int> left = ring;
  double clipped_area2 = 0.0;
  while (left.size() > 3)
  {
    const int n = static_cast<int>(left.size());
    bool clipped = false;
    for (int k = 0; k < n && !clipped; ++k)
    {
      const int a = left[(k + n - 1) % n];
      const int b = left[k];
      const int c = left[(k + 1) % n];
      const double turn = cross2(points[b] - points[a], points[c] - points[b]);
      if (!(turn > eps))
      {
        continue;  // reflex or collinear: not an ear tip
      }
      bool empty = true;
      for (int other : left)
      {
        if (other != a && other != b && other != c && points[other] != points[a] && points[other] != points[b] &&
            points[other] != points[c] && inTriangle(points[other], points[a], points[b], points[c], eps))
        {
          empty = false;
          break;
        }
      }
      if (!empty)
      {
        continue;
      }
      triangles->push_back({a, b, c});
      clipped_area2 += turn;
      left.erase(left.begin() + k);
      clipped = true;
    }
    if (!clipped)
    {
      // Only collinear corners may be left (a straight polygon remainder: no area), else the
      // polygon crosses itself.
      break;
    }
  }
  if (left.size() == 3)
  {
    const double turn = cross2(points[left[1]] - points[left[0]], points[left[2]] - points[left[1]]);
    if (turn > eps)
    {
      triangles->push_back({left[0], left[1], left[2]});
      clipped_area2 += turn;
    }
  }
  // The triangles must cover exactly the polygon's area: a self-intersecting polygon does not.
  if (std::abs(clipped_area2 - area2) > 1e-9 * area2)
  {
    triangles->clear();
    return "polygon of " + std::to_string(corners.size()) + " corners crosses itself and cannot be triangulated";
  }
  return "";
}
}  // namespace god_finger
