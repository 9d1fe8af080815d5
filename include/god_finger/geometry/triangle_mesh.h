// Triangle mesh with the god-finger neighbour table (paper, section 3.2), built once at load.
//
// Units: vertex coordinates in metres, in the mesh's own frame.
// Invariants after TriangleMesh::build():
//  - every triangle has three distinct vertices and non-zero area (degenerate ones removed);
//  - duplicate vertices (closer than weld_tolerance) are welded into one;
//  - winding is made consistent across every manifold edge of each orientable component,
//    and closed components are wound counter-clockwise seen from outside (positive volume),
//    so normals() point out of the object;
//  - edge k of triangle t runs from vertex triangles()[t][k] to triangles()[t][(k+1)%3]; the
//    vertex opposite edge k is triangles()[t][(k+2)%3]; barycentric coordinate j belongs to
//    vertex triangles()[t][j];
//  - neighbours()[t][k] is the triangle across edge k, kBoundaryEdge where no triangle is
//    there, kNonManifoldEdge where more than two triangles share the edge;
//  - sourceTriangle(t) is the index of triangle t in the input (the file's own order).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

namespace god_finger
{
// Vertices and triangles as they come from a file or a generator, before any repair.
struct TriangleSoup
{
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
};

// What build() found and did. Repaired defects are counted; the rest are reported.
struct MeshHealth
{
  int input_vertices = 0;
  int input_triangles = 0;
  int welded_vertices = 0;             // repaired: duplicate vertices merged
  int degenerate_triangles = 0;        // repaired: removed (zero area or repeated vertex)
  int duplicate_triangles = 0;         // repaired: removed (same three vertices as another)
  int flipped_triangles = 0;           // repaired: winding made consistent / outward
  int boundary_edges = 0;              // reported: edges with one triangle (holes, open meshes)
  int non_manifold_edges = 0;          // reported: edges with more than two triangles
  int inconsistent_winding_edges = 0;  // reported: left after repair (non-orientable surface)
  int components = 0;                  // connected through manifold edges
};

struct MeshBuildOptions
{
  // Vertices closer than this are one vertex, relative to the bounding-box diagonal.
  double relative_weld_tolerance = 1e-9;
  // A triangle is degenerate when 2*area < this * (longest edge)^2 (a needle of aspect ratio
  // 1e-8 is still kept: it is valid geometry and the walk handles it).
  double relative_area_tolerance = 1e-12;
};

class TriangleMesh
{
 public:
  static constexpr int kBoundaryEdge = -1;
  static constexpr int kNonManifoldEdge = -2;

  // Repairs and indexes a soup. Throws InputError on non-finite coordinates, indices out of
  // range, or when no triangle is left.
  static TriangleMesh build(const TriangleSoup& soup, const MeshBuildOptions& options = MeshBuildOptions());

  // Moves every vertex to `positions` (same count and order: a deformed soft body's surface),
  // the triangles and neighbours kept; normals, barycentric gradients and the bounding box
  // follow. A triangle squashed to no area keeps its last normal and gradients (the walk stays
  // finite). Real-time safe: allocates nothing. InputError on a count that is not
  // vertexCount() or a non-finite position (the mesh unchanged).
  void moveVertices(const std::vector<Eigen::Vector3d>& positions);

  const std::vector<Eigen::Vector3d>& vertices() const
  {
    return vertices_;
  }
  const std::vector<Eigen::Vector3i>& triangles() const
  {
    return triangles_;
  }
  const std::vector<Eigen::Vector3d>& normals() const
  {
    return normals_;
  }
  const std::vector<Eigen::Vector3i>& neighbours() const
  {
    return neighbours_;
  }
  // Barycentric gradients of a triangle (1/m, in its plane): d(lambda_j) = gradient(t, j) . dp.
  // Precomputed for corners 0 and 1 (48 bytes per triangle); corner 2's is minus their sum.
  // What the surface walk needs per face, so that an edge crossing costs no division or root.
  Eigen::Vector3d barycentricGradient(int triangle, int local_vertex) const
  {
    const BarycentricGradients& g = gradients_[triangle];
    return local_vertex == 0 ? g.first : (local_vertex == 1 ? g.second : Eigen::Vector3d(-g.first - g.second));
  }
  int triangleCount() const
  {
    return static_cast<int>(triangles_.size());
  }
  int vertexCount() const
  {
    return static_cast<int>(vertices_.size());
  }
  int sourceTriangle(int triangle) const
  {
    return source_triangle_[triangle];
  }
  const MeshHealth& health() const
  {
    return health_;
  }
  // Triangles incident to a vertex, in no particular order.
  const int* vertexFacesBegin(int vertex) const
  {
    return vertex_faces_.data() + vertex_face_offsets_[vertex];
  }
  const int* vertexFacesEnd(int vertex) const
  {
    return vertex_faces_.data() + vertex_face_offsets_[vertex + 1];
  }
  const Eigen::Vector3d& corner(int triangle, int local_vertex) const
  {
    return vertices_[triangles_[triangle][local_vertex]];
  }
  // Local index (0..2) of a global vertex in a triangle, -1 if absent.
  int localVertex(int triangle, int vertex) const
  {
    const Eigen::Vector3i& t = triangles_[triangle];
    return t[0] == vertex ? 0 : (t[1] == vertex ? 1 : (t[2] == vertex ? 2 : -1));
  }
  double boundingBoxDiagonal() const
  {
    return bounding_box_diagonal_;
  }
  // Bytes held by this mesh (vertices, triangles, normals, gradients, neighbour and vertex
  // tables).
  std::size_t memoryBytes() const;

 private:
  // build()'s last stage: normals, barycentric gradients and the vertex -> faces table, from
  // vertices_ and triangles_.
  void buildTables();
  // Triangle t's normal and barycentric gradients from vertices_; false (nothing changed) for a
  // triangle of no area.
  bool updateTriangleFrame(int t);
  std::vector<Eigen::Vector3d> vertices_;
  std::vector<Eigen::Vector3i> triangles_;
  std::vector<Eigen::Vector3d> normals_;
  std::vector<Eigen::Vector3i> neighbours_;
  struct BarycentricGradients
  {
    Eigen::Vector3d first;
    Eigen::Vector3d second;
  };
  std::vector<BarycentricGradients> gradients_;
  std::vector<int> vertex_face_offsets_;
  std::vector<int> vertex_faces_;
  std::vector<int> source_triangle_;
  MeshHealth health_;
  double bounding_box_diagonal_ = 0.0;
};
}  // namespace god_finger
