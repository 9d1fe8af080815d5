// Ear clipping of concave polygon faces: an L, a U, a star, a comb, a polygon with collinear
// runs and repeated corners, a non-planar one: every triangle inside the polygon, turning the
// polygon's way, the areas adding up to the polygon's; a self-intersecting polygon refused.
#include "god_finger/geometry/polygon_triangulation.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

namespace god_finger
{
namespace
{
using Polygon = std::vector<Eigen::Vector3d>;

Polygon flat(const std::vector<std::array<double, 2>>& xy)
{
  Polygon result;
  for (const auto& p : xy)
  {
    result.emplace_back(p[0], p[1], 0.0);
  }
  return result;
}

double shoelace(const Polygon& polygon)
{
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i)
  {
    const Eigen::Vector3d& a = polygon[i];
    const Eigen::Vector3d& b = polygon[(i + 1) % polygon.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * twice;
}

bool insidePolygon(const Polygon& polygon, const Eigen::Vector3d& p)
{
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
  {
    const Eigen::Vector3d& a = polygon[i];
    const Eigen::Vector3d& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
    {
      inside = !inside;
    }
  }
  return inside;
}

// Every triangle inside, none flipped, areas adding up to the polygon's (counter-clockwise, z = 0).
void expectExactCover(const Polygon& polygon, const std::string& name)
{
  SCOPED_TRACE(name);
  std::vector<std::array<int, 3>> triangles;
  ASSERT_EQ(triangulatePolygon(polygon, &triangles), "");
  double total = 0.0;
  for (const auto& t : triangles)
  {
    const Eigen::Vector3d& a = polygon[t[0]];
    const Eigen::Vector3d& b = polygon[t[1]];
    const Eigen::Vector3d& c = polygon[t[2]];
    const double area = 0.5 * (b - a).cross(c - a).z();
    EXPECT_GT(area, 0.0) << "flipped or degenerate triangle";
    EXPECT_TRUE(insidePolygon(polygon, (a + b + c) / 3.0)) << "triangle outside the polygon";
    total += area;
  }
  EXPECT_NEAR(total, shoelace(polygon), 1e-12 * std::abs(shoelace(polygon)));
}

TEST(PolygonTriangulation, ConcaveShapesAreCoveredExactly)
{
  expectExactCover(flat({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}), "L");
  expectExactCover(flat({{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}), "U");
  Polygon star;
  for (int k = 0; k < 10; ++k)
  {
    const double r = k % 2 ? 0.4 : 1.0;
    star.emplace_back(r * std::cos(0.2 * M_PI * k), r * std::sin(0.2 * M_PI * k), 0.0);
  }
  expectExactCover(star, "star");
  // Five teeth 1 wide and 2 deep on a bar 1 thick.
  Polygon comb = flat({{0, 0}, {9, 0}, {9, 3}});
  for (int x = 8; x >= 2; x -= 2)
  {
    for (const std::array<double, 2>& p :
         std::vector<std::array<double, 2>>{{double(x), 3}, {double(x), 1}, {x - 1.0, 1}, {x - 1.0, 3}})
    {
      comb.emplace_back(p[0], p[1], 0.0);
    }
  }
  comb.emplace_back(0, 3, 0);
  expectExactCover(comb, "comb");
  // Collinear runs along the edges (a T-junction with neighbouring faces stays a vertex).
  expectExactCover(flat({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {1, 2}, {1, 1}, {0, 1}}), "collinear runs");
  // A square with a square hole, as files without holes carry it: one polygon whose outer ring
  // and (clockwise) hole are joined by a bridge walked both ways (its ends repeat).
  const Polygon keyhole = flat({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}, {1, 1}, {1, 3}, {3, 3}, {3, 1}, {1, 1}});
  EXPECT_DOUBLE_EQ(shoelace(keyhole), 12.0);
  expectExactCover(keyhole, "square with a hole (keyhole)");
  std::vector<std::array<int, 3>> triangles;
  ASSERT_EQ(triangulatePolygon(keyhole, &triangles), "");
  for (const auto& t : triangles)
  {
    const Eigen::Vector3d centre = (keyhole[t[0]] + keyhole[t[1]] + keyhole[t[2]]) / 3.0;
    EXPECT_FALSE(centre.x() > 1 && centre.x() < 3 && centre.y() > 1 && centre.y() < 3) << "a triangle in the hole";
  }
}

TEST(PolygonTriangulation, RepeatedCornersAndNoAreaAreHandled)
{
  std::vector<std::array<int, 3>> triangles;
  const Polygon repeated = flat({{0, 0}, {2, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 3}, {0, 3}, {0, 0}});
  ASSERT_EQ(triangulatePolygon(repeated, &triangles), "");
  double total = 0.0;
  for (const auto& t : triangles)
  {
    total += 0.5 * (repeated[t[1]] - repeated[t[0]]).cross(repeated[t[2]] - repeated[t[0]]).z();
  }
  EXPECT_NEAR(total, 4.0, 1e-12);
  EXPECT_EQ(triangulatePolygon(flat({{0, 0}, {1, 0}, {2, 0}, {3, 0}}), &triangles), "");
  EXPECT_TRUE(triangles.empty());
}

TEST(PolygonTriangulation, NonPlanarPolygonsGoThroughTheirBestFitPlane)
{
  // An L bent 1 % out of its plane and turned into an arbitrary orientation.
  Polygon bent = flat({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 3}, {0, 3}});
  bent[3].z() = 0.02;
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  for (Eigen::Vector3d& p : bent)
  {
    p = turn * p + Eigen::Vector3d(5, -2, 1);
  }
  std::vector<std::array<int, 3>> triangles;
  ASSERT_EQ(triangulatePolygon(bent, &triangles), "");
  EXPECT_EQ(triangles.size(), 4u);
  const Eigen::Vector3d normal = turn * Eigen::Vector3d::UnitZ();
  for (const auto& t : triangles)
  {
    EXPECT_GT((bent[t[1]] - bent[t[0]]).cross(bent[t[2]] - bent[t[0]]).dot(normal), 0.0);
  }
}

TEST(PolygonTriangulation, SelfIntersectingPolygonIsRefused)
{
  std::vector<std::array<int, 3>> triangles;
  EXPECT_EQ(triangulatePolygon(flat({{0, 0}, {2, 2}, {2, 0}, {0, 2}, {-1, 1}}), &triangles),
            "polygon of 5 corners crosses itself and cannot be triangulated");
  // A symmetric bow tie: its two lobes cancel, no net area, yet not a line.
  EXPECT_EQ(triangulatePolygon(flat({{0, 0}, {2, 2}, {2, 0}, {0, 2}}), &triangles),
            "polygon of 4 corners crosses itself and cannot be triangulated");
  EXPECT_TRUE(triangles.empty());
}
}  // namespace
}  // namespace god_finger
