// Mesh building: welding, degenerate and duplicate removal, the neighbour table, winding
// repair, and clear errors on bad input.
#include "god_finger/geometry/triangle_mesh.h"
#include "god_finger/support/input_error.h"
#include "god_finger/geometry/mesh_primitives.h"
#include "test_meshes.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <cmath>
#include <limits>

namespace god_finger
{
namespace
{
// Every neighbour entry is symmetric and shares exactly the edge's two vertices.
void expectConsistentNeighbours(const TriangleMesh& mesh)
{
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int u = mesh.neighbours()[t][k];
      if (u < 0)
      {
        continue;
      }
      const int a = mesh.triangles()[t][k];
      const int b = mesh.triangles()[t][(k + 1) % 3];
      ASSERT_GE(mesh.localVertex(u, a), 0);
      ASSERT_GE(mesh.localVertex(u, b), 0);
      // Consistent winding: the neighbour runs the shared edge the other way.
      const int la = mesh.localVertex(u, a);
      const int lb = mesh.localVertex(u, b);
      EXPECT_EQ((lb + 1) % 3, la) << "triangles " << t << " and " << u;
      bool back = false;
      for (int j = 0; j < 3; ++j)
      {
        back = back || mesh.neighbours()[u][j] == t;
      }
      EXPECT_TRUE(back);
    }
  }
}

TEST(TriangleMesh, StlStyleCubeWeldsToEightVertices)
{
  const TriangleMesh mesh = TriangleMesh::build(test::duplicatedVerticesCube());
  EXPECT_EQ(mesh.health().input_vertices, 36);
  EXPECT_EQ(mesh.vertexCount(), 8);
  EXPECT_EQ(mesh.health().welded_vertices, 28);
  EXPECT_EQ(mesh.triangleCount(), 12);
  EXPECT_EQ(mesh.health().boundary_edges, 0);
  EXPECT_EQ(mesh.health().non_manifold_edges, 0);
  EXPECT_EQ(mesh.health().flipped_triangles, 0);
  EXPECT_EQ(mesh.health().components, 1);
  expectConsistentNeighbours(mesh);
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    const Eigen::Vector3d centroid = (mesh.corner(t, 0) + mesh.corner(t, 1) + mesh.corner(t, 2)) / 3.0;
    EXPECT_NEAR(mesh.normals()[t].norm(), 1.0, 1e-15);
    EXPECT_GT(mesh.normals()[t].dot(centroid), 0.0);  // outward
    EXPECT_EQ(mesh.sourceTriangle(t), t);
  }
}

TEST(TriangleMesh, DegenerateAndDuplicateTrianglesAreRemovedAndCounted)
{
  TriangleSoup soup = makeGrid(1.0, 2);  // 8 triangles; the first is (0, 1, 4)
  const int grid_triangles = static_cast<int>(soup.triangles.size());
  soup.vertices.emplace_back(0.3, 0.3, 0.0);
  soup.vertices.emplace_back(0.6, 0.6, 0.0);
  soup.vertices.emplace_back(0.9, 0.9, 0.0);
  const int v = static_cast<int>(soup.vertices.size()) - 3;
  soup.triangles.push_back({v, v + 1, v + 2});  // collinear: zero area
  soup.triangles.push_back({0, 0, 1});          // repeated vertex
  soup.triangles.push_back(soup.triangles[3]);  // exact duplicate
  soup.triangles.push_back({1, 0, 4});          // triangle 0 again, reversed
  soup.triangles.push_back({2, 5, 8});          // the grid's right border: collinear
  const TriangleMesh mesh = TriangleMesh::build(soup);
  EXPECT_EQ(mesh.health().degenerate_triangles, 3);
  EXPECT_EQ(mesh.health().duplicate_triangles, 2);
  ASSERT_EQ(mesh.triangleCount(), grid_triangles);
  for (int t = 0; t < grid_triangles; ++t)
  {
    EXPECT_EQ(mesh.sourceTriangle(t), t);  // the first of duplicates is kept, in file order
  }
  EXPECT_EQ(mesh.health().boundary_edges, 8);
  EXPECT_EQ(mesh.health().non_manifold_edges, 0);
}

TEST(TriangleMesh, SourceTriangleFollowsTheFileOrderAfterRemovals)
{
  TriangleSoup soup = makeGrid(1.0, 1);                      // (0, 1, 3), (0, 3, 2)
  soup.triangles.insert(soup.triangles.begin(), {0, 0, 3});  // degenerate, first in the file
  const TriangleMesh mesh = TriangleMesh::build(soup);
  ASSERT_EQ(mesh.triangleCount(), 2);
  EXPECT_EQ(mesh.sourceTriangle(0), 1);
  EXPECT_EQ(mesh.sourceTriangle(1), 2);
}

TEST(TriangleMesh, HolesGiveTheExactBoundaryCount)
{
  TriangleSoup soup = makeGrid(1.0, 4);  // 32 triangles, 16 outer border edges
  EXPECT_EQ(TriangleMesh::build(soup).health().boundary_edges, 16);
  // Remove both triangles of one inner cell: 4 more border edges.
  soup.triangles.erase(soup.triangles.begin() + 10, soup.triangles.begin() + 12);
  const TriangleMesh mesh = TriangleMesh::build(soup);
  EXPECT_EQ(mesh.health().boundary_edges, 20);
  expectConsistentNeighbours(mesh);
  int boundary_entries = 0;
  for (const Eigen::Vector3i& n : mesh.neighbours())
  {
    for (int k = 0; k < 3; ++k)
    {
      boundary_entries += n[k] == TriangleMesh::kBoundaryEdge;
    }
  }
  EXPECT_EQ(boundary_entries, 20);
}

TEST(TriangleMesh, NonManifoldEdgesAreMarked)
{
  TriangleSoup soup;
  soup.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0.2, 0.2, 1}};
  soup.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};  // edge 0-1 has three triangles
  const TriangleMesh mesh = TriangleMesh::build(soup);
  EXPECT_EQ(mesh.health().non_manifold_edges, 1);
  for (int t = 0; t < 3; ++t)
  {
    int marked = 0;
    for (int k = 0; k < 3; ++k)
    {
      marked += mesh.neighbours()[t][k] == TriangleMesh::kNonManifoldEdge;
    }
    EXPECT_EQ(marked, 1);
  }
}

TEST(TriangleMesh, InconsistentWindingIsRepaired)
{
  const TriangleMesh mesh = TriangleMesh::build(test::inconsistentWindingCube());
  EXPECT_EQ(mesh.health().flipped_triangles, 3);
  EXPECT_EQ(mesh.health().inconsistent_winding_edges, 0);
  expectConsistentNeighbours(mesh);
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    EXPECT_GT(mesh.normals()[t].dot(mesh.corner(t, 0) + mesh.corner(t, 1) + mesh.corner(t, 2)), 0.0);
  }
}

TEST(TriangleMesh, InsideOutClosedMeshIsTurnedOutward)
{
  const TriangleMesh mesh = TriangleMesh::build(test::insideOutCube());
  EXPECT_EQ(mesh.health().flipped_triangles, 12);
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    EXPECT_GT(mesh.normals()[t].dot(mesh.corner(t, 0) + mesh.corner(t, 1) + mesh.corner(t, 2)), 0.0);
  }
}

TEST(TriangleMesh, MoebiusStripIsReportedNotFixed)
{
  const TriangleMesh mesh = TriangleMesh::build(test::moebiusSoup());
  EXPECT_EQ(mesh.triangleCount(), 16);
  EXPECT_EQ(mesh.health().inconsistent_winding_edges, 1);
  EXPECT_EQ(mesh.health().boundary_edges, 16);
}

TEST(TriangleMesh, HighValenceVertexFan)
{
  const TriangleMesh mesh = TriangleMesh::build(test::highValenceConeSoup(32));
  EXPECT_EQ(mesh.vertexFacesEnd(0) - mesh.vertexFacesBegin(0), 32);
  EXPECT_EQ(mesh.health().boundary_edges, 0);
  expectConsistentNeighbours(mesh);
}

TEST(TriangleMesh, BadInputThrowsAClearError)
{
  TriangleSoup soup = makeBox(Eigen::Vector3d::Constant(0.5));
  soup.vertices[3].y() = std::numeric_limits<double>::quiet_NaN();
  try
  {
    TriangleMesh::build(soup);
    FAIL() << "no error for a NaN vertex";
  }
  catch (const InputError& error)
  {
    EXPECT_STREQ(error.what(), "vertex 3 has a non-finite coordinate (0.5, nan, -0.5)");
  }
  soup = makeBox(Eigen::Vector3d::Constant(0.5));
  soup.triangles[5][1] = 8;
  try
  {
    TriangleMesh::build(soup);
    FAIL() << "no error for an index out of range";
  }
  catch (const InputError& error)
  {
    EXPECT_STREQ(error.what(), "triangle 5 refers to vertex 8, out of range [0, 8)");
  }
  soup.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  soup.triangles = {{0, 1, 2}, {0, 0, 1}};
  try
  {
    TriangleMesh::build(soup);
    FAIL() << "no error for an all-degenerate soup";
  }
  catch (const InputError& error)
  {
    EXPECT_STREQ(error.what(), "no non-degenerate triangles (2 in the input, all degenerate or repeated)");
  }
  EXPECT_THROW(TriangleMesh::build(TriangleSoup()), InputError);
}

TEST(TriangleMesh, FarFromTheOriginAndTinyScale)
{
  for (const double scale : {1e-3, 1.0, 1e3})
  {
    const TriangleMesh mesh =
        TriangleMesh::build(test::transformed(test::duplicatedVerticesCube(), scale, Eigen::Vector3d(1e4, 0, -1e4)));
    EXPECT_EQ(mesh.vertexCount(), 8) << scale;
    EXPECT_EQ(mesh.health().boundary_edges, 0) << scale;
    EXPECT_EQ(mesh.health().flipped_triangles, 0) << scale;
  }
}
}  // namespace
}  // namespace god_finger
