#include "god_finger/geometry/mesh_primitives.h"

#include "god_finger/support/input_error.h"

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace god_finger
{
namespace
{
void requirePositive(double value, const char* what)
{
  if (!(value > 0.0) || !std::isfinite(value))
  {
    throw InputError(std::string(what) + " must be positive and finite, got " + std::to_string(value));
  }
}

// Adds the two triangles of quad a-b-c-d (counter-clockwise seen from outside).
void addQuad(TriangleSoup* soup, int a, int b, int c, int d)
{
  soup->triangles.push_back({a, b, c});
  soup->triangles.push_back({a, c, d});
}
}  // namespace

TriangleSoup makeBox(const Eigen::Vector3d& half_extents)
{
  requirePositive(half_extents.minCoeff(), "box half extents");
  TriangleSoup soup;
  for (int i = 0; i < 8; ++i)
  {
    soup.vertices.emplace_back((i & 1 ? 1 : -1) * half_extents.x(), (i & 2 ? 1 : -1) * half_extents.y(),
                               (i & 4 ? 1 : -1) * half_extents.z());
  }
  addQuad(&soup, 0, 2, 3, 1);  // -z
  addQuad(&soup, 4, 5, 7, 6);  // +z
  addQuad(&soup, 0, 1, 5, 4);  // -y
  addQuad(&soup, 2, 6, 7, 3);  // +y
  addQuad(&soup, 0, 4, 6, 2);  // -x
  addQuad(&soup, 1, 3, 7, 5);  // +x
  return soup;
}

TriangleSoup makeIcosphere(double radius, int subdivisions)
{
  requirePositive(radius, "sphere radius");
  if (subdivisions < 0 || subdivisions > 8)
  {
    throw InputError("icosphere subdivisions must be in [0, 8], got " + std::to_string(subdivisions));
  }
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  TriangleSoup soup;
  const double base[12][3] = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                              {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (const auto& v : base)
  {
    soup.vertices.push_back(Eigen::Vector3d(v[0], v[1], v[2]).normalized());
  }
  soup.triangles = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                    {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                    {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int level = 0; level < subdivisions; ++level)
  {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b)
    {
      const std::pair<int, int> key(std::min(a, b), std::max(a, b));
      const auto found = midpoints.find(key);
      if (found != midpoints.end())
      {
        return found->second;
      }
      const int index = static_cast<int>(soup.vertices.size());
      soup.vertices.push_back((soup.vertices[a] + soup.vertices[b]).normalized());
      midpoints.emplace(key, index);
      return index;
    };
    std::vector<std::array<int, 3>> finer;
    finer.reserve(4 * soup.triangles.size());
    for (const auto& tri : soup.triangles)
    {
      const int ab = midpoint(tri[0], tri[1]);
      const int bc = midpoint(tri[1], tri[2]);
      const int ca = midpoint(tri[2], tri[0]);
      finer.push_back({tri[0], ab, ca});
      finer.push_back({tri[1], bc, ab});
      finer.push_back({tri[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    soup.triangles.swap(finer);
  }
  for (Eigen::Vector3d& v : soup.vertices)
  {
    v *= radius;
  }
  return soup;
}

TriangleSoup makeCylinder(double radius, double length, int segments)
{
  requirePositive(radius, "cylinder radius");
  requirePositive(length, "cylinder length");
  if (segments < 3)
  {
    throw InputError("cylinder needs at least 3 segments, got " + std::to_string(segments));
  }
  TriangleSoup soup;
  const double h = length / 2.0;
  for (int i = 0; i < segments; ++i)
  {
    const double a = 2.0 * M_PI * i / segments;
    soup.vertices.emplace_back(radius * std::cos(a), radius * std::sin(a), -h);
    soup.vertices.emplace_back(radius * std::cos(a), radius * std::sin(a), h);
  }
  const int bottom = static_cast<int>(soup.vertices.size());
  soup.vertices.emplace_back(0.0, 0.0, -h);
  const int top = bottom + 1;
  soup.vertices.emplace_back(0.0, 0.0, h);
  for (int i = 0; i < segments; ++i)
  {
    const int j = (i + 1) % segments;
    addQuad(&soup, 2 * i, 2 * j, 2 * j + 1, 2 * i + 1);
    soup.triangles.push_back({bottom, 2 * j, 2 * i});
    soup.triangles.push_back({top, 2 * i + 1, 2 * j + 1});
  }
  return soup;
}

TriangleSoup makeGrid(double half_size, int cells)
{
  requirePositive(half_size, "grid half size");
  if (cells < 1)
  {
    throw InputError("grid needs at least 1 cell, got " + std::to_string(cells));
  }
  TriangleSoup soup;
  const double step = 2.0 * half_size / cells;
  for (int j = 0; j <= cells; ++j)
  {
    for (int i = 0; i <= cells; ++i)
    {
      // Exact at the borders, so that grids of different resolution cover the same square.
      const double x = i == cells ? half_size : -half_size + i * step;
      const double y = j == cells ? half_size : -half_size + j * step;
      soup.vertices.emplace_back(x, y, 0.0);
    }
  }
  const int row = cells + 1;
  for (int j = 0; j < cells; ++j)
  {
    for (int i = 0; i < cells; ++i)
    {
      const int a = j * row + i;
      addQuad(&soup, a, a + 1, a + row + 1, a + row);  // diagonal a -> a + row + 1
    }
  }
  return soup;
}

TriangleSoup makeTorus(double major_radius, double minor_radius, int major_segments, int minor_segments)
{
  requirePositive(major_radius, "torus major radius");
  requirePositive(minor_radius, "torus minor radius");
  if (minor_radius >= major_radius)
  {
    throw InputError("torus minor radius must be smaller than the major radius");
  }
  if (major_segments < 3 || minor_segments < 3)
  {
    throw InputError("torus needs at least 3 segments each way");
  }
  TriangleSoup soup;
  for (int i = 0; i < major_segments; ++i)
  {
    const double u = 2.0 * M_PI * i / major_segments;
    for (int j = 0; j < minor_segments; ++j)
    {
      const double v = 2.0 * M_PI * j / minor_segments;
      const double ring = major_radius + minor_radius * std::cos(v);
      soup.vertices.emplace_back(ring * std::cos(u), ring * std::sin(u), minor_radius * std::sin(v));
    }
  }
  for (int i = 0; i < major_segments; ++i)
  {
    const int i1 = (i + 1) % major_segments;
    for (int j = 0; j < minor_segments; ++j)
    {
      const int j1 = (j + 1) % minor_segments;
      addQuad(&soup, i * minor_segments + j, i1 * minor_segments + j, i1 * minor_segments + j1,
              i * minor_segments + j1);
    }
  }
  return soup;
}

TriangleSoup makeLBlock(double arm, double depth)
{
  requirePositive(arm, "L block arm");
  requirePositive(depth, "L block depth");
  // The L profile in the x-z plane, counter-clockwise in (x, z); extruded along y.
  const double a = arm;
  const std::vector<Eigen::Vector2d> profile = {{0, 0}, {2 * a, 0}, {2 * a, a}, {a, a}, {a, 2 * a}, {0, 2 * a}, {0, a}};
  const int n = static_cast<int>(profile.size());
  TriangleSoup soup;
  for (int side = 0; side < 2; ++side)
  {
    const double y = side == 0 ? -depth / 2 : depth / 2;
    for (const Eigen::Vector2d& p : profile)
    {
      soup.vertices.emplace_back(p.x(), y, p.y());
    }
  }
  // Walls: profile edge i -> i+1 on the front (y-) and back (y+).
  for (int i = 0; i < n; ++i)
  {
    const int j = (i + 1) % n;
    addQuad(&soup, i, n + i, n + j, j);
  }
  // Caps: the L split into convex pieces (indices into the profile).
  const std::vector<std::array<int, 3>> cap = {{0, 1, 2}, {0, 2, 3}, {0, 3, 6}, {6, 3, 4}, {6, 4, 5}};
  for (const auto& t : cap)
  {
    // Counter-clockwise in (x, z) faces -y: as is on the front cap, reversed on the back.
    soup.triangles.push_back({t[0], t[1], t[2]});
    soup.triangles.push_back({n + t[0], n + t[2], n + t[1]});
  }
  return soup;
}
TriangleSoup makeRevolved(const std::vector<Eigen::Vector2d>& profile, int segments)
{
  if (segments < 3)
  {
    throw InputError("a revolved shape needs at least 3 segments, got " + std::to_string(segments));
  }
  if (profile.size() < 3)
  {
    throw InputError("a revolved shape needs a profile of at least 3 points");
  }
  for (const Eigen::Vector2d& point : profile)
  {
    if (!std::isfinite(point.x()) || !std::isfinite(point.y()) || point.x() < 0.0)
    {
      throw InputError("a revolved shape's profile needs finite points with r >= 0");
    }
  }
  TriangleSoup soup;
  std::vector<int> first(profile.size());  // each profile point's first vertex (one on the axis)
  for (std::size_t k = 0; k < profile.size(); ++k)
  {
    first[k] = static_cast<int>(soup.vertices.size());
    const int count = profile[k].x() == 0.0 ? 1 : segments;
    for (int i = 0; i < count; ++i)
    {
      const double a = 2.0 * M_PI * i / segments;
      soup.vertices.emplace_back(profile[k].x() * std::cos(a), profile[k].x() * std::sin(a), profile[k].y());
    }
  }
  for (std::size_t k = 0; k + 1 < profile.size(); ++k)
  {
    for (int i = 0; i < segments; ++i)
    {
      const int j = (i + 1) % segments;
      if (profile[k].x() == 0.0)
      {
        soup.triangles.push_back({first[k], first[k + 1] + j, first[k + 1] + i});
      }
      else if (profile[k + 1].x() == 0.0)
      {
        soup.triangles.push_back({first[k + 1], first[k] + i, first[k] + j});
      }
      else
      {
        addQuad(&soup, first[k] + i, first[k] + j, first[k + 1] + j, first[k + 1] + i);
      }
    }
  }
  return soup;
}

namespace
{
// A cup's profile in (r, z), counter-clockwise (the wall's section on its left): out along the
// bottom, up the outside, in over the rim, down the inside, in along the inner floor.
std::vector<Eigen::Vector2d> cupProfile(double radius, double height, double wall, double bottom)
{
  requirePositive(radius, "cup radius");
  requirePositive(height, "cup height");
  requirePositive(wall, "cup wall");
  requirePositive(bottom, "cup bottom");
  if (wall >= radius || bottom >= height)
  {
    throw InputError("a cup's wall must be thinner than its radius and its bottom lower than its height");
  }
  return {{0.0, 0.0}, {radius, 0.0}, {radius, height}, {radius - wall, height}, {radius - wall, bottom}, {0.0, bottom}};
}
}  // namespace

TriangleSoup makeCup(double radius, double height, double wall, double bottom, int segments)
{
  return makeRevolved(cupProfile(radius, height, wall, bottom), segments);
}

TriangleSoup makePlate(double radius, double height, double thickness, int segments)
{
  requirePositive(radius, "plate radius");
  requirePositive(height, "plate height");
  requirePositive(thickness, "plate thickness");
  if (thickness >= height || thickness >= 0.3 * radius)
  {
    throw InputError("a plate must be thinner than its height and than 0.3 of its radius");
  }
  // A flat floor out to 0.6 of the radius, then a rim sloping up to the full radius.
  const double foot = 0.6 * radius;
  return makeRevolved({{0.0, 0.0},
                       {foot, 0.0},
                       {radius, height},
                       {radius - thickness, height},
                       {foot - thickness / 2.0, thickness},
                       {0.0, thickness}},
                      segments);
}

TriangleSoup makeMug(double radius, double height, double wall, double bottom, int segments)
{
  TriangleSoup soup = makeRevolved(cupProfile(radius, height, wall, bottom), segments);
  // The handle: a torus about z turned into the x-z plane (a rotation keeps its winding).
  const double major = 0.45 * height / 2.0;
  const TriangleSoup ring = makeTorus(major, wall, segments, 8);
  const Eigen::AngleAxisd upright(M_PI / 2.0, Eigen::Vector3d::UnitX());
  const Eigen::Vector3d centre(radius - wall + major + wall, 0.0, height / 2.0);
  const int offset = static_cast<int>(soup.vertices.size());
  for (const Eigen::Vector3d& vertex : ring.vertices)
  {
    soup.vertices.push_back(upright * vertex + centre);
  }
  for (const auto& triangle : ring.triangles)
  {
    soup.triangles.push_back({triangle[0] + offset, triangle[1] + offset, triangle[2] + offset});
  }
  return soup;
}
}  // namespace god_finger
