#include "test_meshes.h"

#include "god_finger/geometry/mesh_primitives.h"

#include <cmath>

namespace god_finger
{
namespace test
{
TriangleSoup transformed(const TriangleSoup& soup, double scale, const Eigen::Vector3d& offset)
{
  TriangleSoup result = soup;
  for (Eigen::Vector3d& v : result.vertices)
  {
    v = scale * v + offset;
  }
  return result;
}

TriangleSoup duplicatedVerticesCube(double half)
{
  const TriangleSoup cube = makeBox(Eigen::Vector3d::Constant(half));
  TriangleSoup result;
  for (const auto& t : cube.triangles)
  {
    const int base = static_cast<int>(result.vertices.size());
    for (int k = 0; k < 3; ++k)
    {
      result.vertices.push_back(cube.vertices[t[k]]);
    }
    result.triangles.push_back({base, base + 1, base + 2});
  }
  return result;
}

TriangleSoup inconsistentWindingCube()
{
  TriangleSoup cube = makeBox(Eigen::Vector3d::Constant(0.5));
  for (int t : {1, 4, 7})
  {
    std::swap(cube.triangles[t][1], cube.triangles[t][2]);
  }
  return cube;
}

TriangleSoup insideOutCube()
{
  TriangleSoup cube = makeBox(Eigen::Vector3d::Constant(0.5));
  for (auto& t : cube.triangles)
  {
    std::swap(t[1], t[2]);
  }
  return cube;
}

TriangleSoup moebiusSoup()
{
  TriangleSoup soup;
  const int segments = 8;
  for (int i = 0; i < segments; ++i)
  {
    const double u = 2.0 * M_PI * i / segments;
    for (double w : {-0.2, 0.2})
    {
      const double r = 1.0 + w * std::cos(u / 2.0);
      soup.vertices.emplace_back(r * std::cos(u), r * std::sin(u), w * std::sin(u / 2.0));
    }
  }
  for (int i = 0; i < segments; ++i)
  {
    const int a = 2 * i;
    const int b = 2 * i + 1;
    // The last quad joins the strip to its start with a half twist.
    const int c = i + 1 < segments ? 2 * (i + 1) + 1 : 0;
    const int d = i + 1 < segments ? 2 * (i + 1) : 1;
    soup.triangles.push_back({a, d, c});
    soup.triangles.push_back({a, c, b});
  }
  return soup;
}

TriangleSoup highValenceConeSoup(int n)
{
  TriangleSoup soup;
  soup.vertices.emplace_back(0.0, 0.0, 1.0);  // apex
  soup.vertices.emplace_back(0.0, 0.0, 0.0);  // base centre
  for (int i = 0; i < n; ++i)
  {
    soup.vertices.emplace_back(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n), 0.0);
  }
  for (int i = 0; i < n; ++i)
  {
    const int a = 2 + i;
    const int b = 2 + (i + 1) % n;
    soup.triangles.push_back({0, a, b});
    soup.triangles.push_back({1, b, a});
  }
  return soup;
}
}  // namespace test
}  // namespace god_finger
