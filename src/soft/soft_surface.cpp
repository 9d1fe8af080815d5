#include "god_finger/soft/soft_surface.h"

#include "god_finger/support/input_error.h"

#include <algorithm>
#include <limits>
#include <map>
#include <tuple>

namespace god_finger
{
SoftSurfaceMesh makeSoftSurfaceMesh(const TetMesh& volume, const std::string& source)
{
  const std::vector<std::array<int, 3>> faces = surfaceTriangles(volume);
  TriangleSoup soup;
  std::vector<int> vertex_of_node(volume.nodes.size(), -1);
  std::vector<int> node_of_soup_vertex;
  for (const std::array<int, 3>& face : faces)
  {
    std::array<int, 3> corners{};
    for (int k = 0; k < 3; ++k)
    {
      int& vertex = vertex_of_node[face[k]];
      if (vertex < 0)
      {
        vertex = static_cast<int>(soup.vertices.size());
        soup.vertices.push_back(volume.nodes[face[k]]);
        node_of_soup_vertex.push_back(face[k]);
      }
      corners[k] = vertex;
    }
    soup.triangles.push_back(corners);
  }
  SoftSurfaceMesh result{TriangleMesh::build(soup), {}};
  if (result.mesh.vertexCount() != static_cast<int>(soup.vertices.size()) ||
      result.mesh.triangleCount() != static_cast<int>(faces.size()))
  {
    throw InputError("'" + source + "': its surface's " + std::to_string(soup.vertices.size()) + " nodes and " +
                     std::to_string(faces.size()) + " faces make a mesh of " +
                     std::to_string(result.mesh.vertexCount()) + " vertices and " +
                     std::to_string(result.mesh.triangleCount()) +
                     " triangles: surface nodes coincide or faces repeat");
  }
  // build() renumbers vertices by first use; the positions are the nodes' own, bit for bit.
  std::map<std::tuple<double, double, double>, int> node_at;
  for (std::size_t v = 0; v < soup.vertices.size(); ++v)
  {
    const Eigen::Vector3d& p = soup.vertices[v];
    node_at[{p.x(), p.y(), p.z()}] = node_of_soup_vertex[v];
  }
  result.node_of_vertex.reserve(result.mesh.vertexCount());
  for (const Eigen::Vector3d& p : result.mesh.vertices())
  {
    result.node_of_vertex.push_back(node_at.at({p.x(), p.y(), p.z()}));
  }
  return result;
}

std::vector<int> nodesGluedToSupport(const TetMesh& volume, const Eigen::Isometry3d& body_in_world)
{
  double lowest = std::numeric_limits<double>::infinity();
  double highest = -lowest;
  for (const Eigen::Vector3d& node : volume.nodes)
  {
    const double z = (body_in_world * node).z();
    lowest = std::min(lowest, z);
    highest = std::max(highest, z);
  }
  const double band = std::max(kGlueMinBand, kGlueHeightFraction * (highest - lowest));
  std::vector<int> glued;
  for (std::size_t i = 0; i < volume.nodes.size(); ++i)
  {
    if ((body_in_world * volume.nodes[i]).z() <= lowest + band)
    {
      glued.push_back(static_cast<int>(i));
    }
  }
  return glued;
}
}  // namespace god_finger
