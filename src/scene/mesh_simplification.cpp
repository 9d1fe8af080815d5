#include "god_finger/scene/mesh_simplification.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <vector>

namespace god_finger
{
SimplifiedMesh simplifyMesh(const TriangleMesh& mesh, int target_triangles, double max_error)
{
  SimplifiedMesh result;
  std::vector<unsigned int> indices;
  indices.reserve(3 * mesh.triangles().size());
  for (const Eigen::Vector3i& t : mesh.triangles())
  {
    indices.insert(indices.end(), {unsigned(t[0]), unsigned(t[1]), unsigned(t[2])});
  }
  if (mesh.triangleCount() > target_triangles)
  {
    // meshoptimizer works in float, relative to the mesh's extent: positions relative to the
    // bounding box's lower corner keep float's 1e-7 relative precision for far-off meshes.
    Eigen::Vector3d lower = mesh.vertices().front();
    for (const Eigen::Vector3d& v : mesh.vertices())
    {
      lower = lower.cwiseMin(v);
    }
    std::vector<float> positions;
    positions.reserve(3 * mesh.vertices().size());
    for (const Eigen::Vector3d& v : mesh.vertices())
    {
      const Eigen::Vector3d p = v - lower;
      positions.insert(positions.end(), {float(p.x()), float(p.y()), float(p.z())});
    }
    const float scale = meshopt_simplifyScale(positions.data(), mesh.vertices().size(), 3 * sizeof(float));
    std::vector<unsigned int> kept(indices.size());
    float relative_error = 0.0f;
    const std::size_t count =
        meshopt_simplify(kept.data(), indices.data(), indices.size(), positions.data(), mesh.vertices().size(),
                         3 * sizeof(float), 3 * static_cast<std::size_t>(std::max(target_triangles, 1)),
                         static_cast<float>(max_error / scale), 0, &relative_error);
    kept.resize(count);
    if (count >= 3)
    {
      indices.swap(kept);
      result.error = static_cast<double>(relative_error) * scale;
    }
  }
  std::vector<int> compact(mesh.vertices().size(), -1);
  result.soup.triangles.reserve(indices.size() / 3);
  for (std::size_t i = 0; i + 2 < indices.size(); i += 3)
  {
    std::array<int, 3> triangle{};
    for (int k = 0; k < 3; ++k)
    {
      int& index = compact[indices[i + k]];
      if (index < 0)
      {
        index = static_cast<int>(result.soup.vertices.size());
        result.soup.vertices.push_back(mesh.vertices()[indices[i + k]]);
      }
      triangle[k] = index;
    }
    result.soup.triangles.push_back(triangle);
  }
  return result;
}
}  // namespace god_finger
