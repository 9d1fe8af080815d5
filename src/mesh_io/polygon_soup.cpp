#include "god_finger/mesh_io/polygon_soup.h"

#include "god_finger/support/input_error.h"
#include "god_finger/geometry/polygon_triangulation.h"

#include <string>

namespace god_finger
{
void appendTriangulated(const PolygonSoup& polygons, TriangleSoup* soup, long long max_vertices)
{
  const long long vertex_count = static_cast<long long>(polygons.vertices.size());
  const long long total = static_cast<long long>(soup->vertices.size()) + vertex_count;
  if (total > max_vertices)
  {
    throw InputError("mesh has " + std::to_string(total) + " vertices, more than the " + std::to_string(max_vertices) +
                     " its triangles can index");
  }
  std::vector<std::array<int, 3>> triangles;
  std::vector<Eigen::Vector3d> corners;
  std::vector<std::array<int, 3>> polygon_triangles;
  for (int f = 0; f < polygons.faceCount(); ++f)
  {
    const std::size_t begin = polygons.face_starts[f];
    const std::size_t end = polygons.face_starts[f + 1];
    const std::size_t count = end - begin;
    if (count < 3)
    {
      continue;
    }
    if (count > static_cast<std::size_t>(kMaxFaceCorners))
    {
      throw InputError("face " + std::to_string(f) + " has " + std::to_string(count) + " corners, more than " +
                       std::to_string(kMaxFaceCorners));
    }
    for (std::size_t k = begin; k < end; ++k)
    {
      if (polygons.corners[k] < 0 || polygons.corners[k] >= vertex_count)
      {
        throw InputError("face " + std::to_string(f) + " refers to vertex " + std::to_string(polygons.corners[k]) +
                         " of " + std::to_string(vertex_count));
      }
    }
    const int base = static_cast<int>(soup->vertices.size());
    const auto vertexOf = [&](std::size_t corner) { return base + static_cast<int>(polygons.corners[corner]); };
    if (count == 3)
    {
      triangles.push_back({vertexOf(begin), vertexOf(begin + 1), vertexOf(begin + 2)});
      continue;
    }
    corners.clear();
    for (std::size_t k = begin; k < end; ++k)
    {
      corners.push_back(polygons.vertices[polygons.corners[k]]);
    }
    const std::string problem = triangulatePolygon(corners, &polygon_triangles);
    if (!problem.empty())
    {
      throw InputError("face " + std::to_string(f) + ": " + problem);
    }
    for (const std::array<int, 3>& t : polygon_triangles)
    {
      triangles.push_back({vertexOf(begin + t[0]), vertexOf(begin + t[1]), vertexOf(begin + t[2])});
    }
  }
  soup->vertices.insert(soup->vertices.end(), polygons.vertices.begin(), polygons.vertices.end());
  soup->triangles.insert(soup->triangles.end(), triangles.begin(), triangles.end());
}
}  // namespace god_finger
