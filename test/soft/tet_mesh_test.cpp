// Tetrahedral meshes and their VTK files: what a user's file (PyBullet's, Gmsh's, meshio's) loads
// to, and the one-line error each bad file gets.
#include "god_finger/soft/tet_mesh.h"
#include "god_finger/soft/block_mesh.h"
#include "god_finger/soft/vtk_tet_reader.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <map>

namespace god_finger
{
namespace
{
const char* const kSingleTet =
    "# vtk DataFile Version 2.0\nball_, Created by Gmsh\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n"
    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n\nCELLS 1 1\n4 0 1 2 3\n\nCELL_TYPES 1\n10\n";

std::string errorOf(const std::string& text)
{
  try
  {
    parseVtkTetMesh(text, "soft.vtk");
  }
  catch (const InputError& error)
  {
    return error.what();
  }
  return "no error";
}

TEST(VtkTetReader, ReadsPyBulletsSingleTetWhoseCellsSizeIsWrong)
{
  const TetMesh mesh = parseVtkTetMesh(kSingleTet, "single_tet.vtk");
  ASSERT_EQ(mesh.nodes.size(), 4u);
  ASSERT_EQ(mesh.tets.size(), 1u);
  EXPECT_NEAR(signedTetVolume(mesh.nodes, mesh.tets[0]), 1.0 / 6.0, 1e-15);
  EXPECT_EQ(surfaceTriangles(mesh).size(), 4u);
}

TEST(VtkTetReader, SkipsGmshsBoundaryCellsAndUnusedPointsAndReorientsANegativeMesh)
{
  // Gmsh writes its points, lines and triangles too; node 5 is used by none of the tetrahedra;
  // both tetrahedra are wound the other way round.
  const std::string text =
      "# vtk DataFile Version 2.0\ngmsh\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 6 double\n"
      "0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n9 9 9\n"
      "CELLS 5 19\n1 5\n2 0 1\n3 0 1 2\n4 0 2 1 3\n4 1 2 4 3\n"
      "CELL_TYPES 5\n1\n3\n5\n10\n10\nCELL_DATA 5\nSCALARS id int 1\nLOOKUP_TABLE default\n1 2 3 4 5\n";
  TetMeshRepairs repairs;
  const TetMesh mesh = parseVtkTetMesh(text, "gmsh.vtk", &repairs);
  EXPECT_EQ(repairs.dropped_nodes, 1);
  EXPECT_TRUE(repairs.reoriented);
  ASSERT_EQ(mesh.nodes.size(), 5u);
  ASSERT_EQ(mesh.tets.size(), 2u);
  for (const auto& tet : mesh.tets)
  {
    EXPECT_GT(signedTetVolume(mesh.nodes, tet), 0.0);
  }
}

TEST(VtkTetReader, ReadsFilesWithoutCellTypesAsBulletDoes)
{
  // Bullet's reduced-deformable meshes: "#vtk", CELLS' size without the counts, a bare
  // "CELL_TYPES 10" at the end.
  const std::string text =
      "#vtk DataFile Version 2.0\nI don't think this matters\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 5 double\n"
      "0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\nCELLS 2 8\n4 0 1 2 3\n4 1 4 2 3\nCELL_TYPES 10\n";
  const TetMesh mesh = parseVtkTetMesh(text, "cube_mesh.vtk");
  EXPECT_EQ(mesh.tets.size(), 2u);
  // Without any CELL_TYPES at all, the same.
  EXPECT_EQ(parseVtkTetMesh(text.substr(0, text.find("CELL_TYPES")), "no_types.vtk").tets.size(), 2u);
}

TEST(VtkTetReader, ReadsTheVersion5Layout)
{
  const std::string text =
      "# vtk DataFile Version 5.1\nmeshio\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 5 float\n"
      "0 0 0 1 0 0 0 1 0 0 0 1 1 1 1\nCELLS 3 8\nOFFSETS vtktypeint64\n0 4 8\nCONNECTIVITY vtktypeint64\n"
      "0 1 2 3 1 4 2 3\nCELL_TYPES 2\n10\n10\n";
  const TetMesh mesh = parseVtkTetMesh(text, "meshio.vtk");
  EXPECT_EQ(mesh.tets.size(), 2u);
  EXPECT_EQ(mesh.tets[1], (std::array<int, 4>{1, 4, 2, 3}));
}

TEST(VtkTetReader, WritesWhatItReadsBackExactly)
{
  BlockMeshSpec spec;
  spec.cells = {2, 3, 2};
  spec.grading = 2.5;
  const TetMesh mesh = blockTetMesh(spec);
  const TetMesh read = parseVtkTetMesh(vtkTetMeshText(mesh, "block"), "block.vtk");
  ASSERT_EQ(read.nodes.size(), mesh.nodes.size());
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
  {
    ASSERT_EQ(read.nodes[n], mesh.nodes[n]);
  }
  EXPECT_EQ(read.tets, mesh.tets);
}

TEST(VtkTetReader, EachBadFileGetsItsOneLineError)
{
  const std::string head = "# vtk DataFile Version 2.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  const std::string points = "POINTS 4 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  const std::map<std::string, std::string> cases = {
      {"solid cube\nfacet normal 0 0 1\n",
       "soft.vtk: not a legacy VTK file (its first line must be '# vtk DataFile Version ...')"},
      {"# vtk DataFile Version 2.0\nt\nBINARY\nDATASET UNSTRUCTURED_GRID\n",
       "soft.vtk: line 3: BINARY VTK files are not read: write it as ASCII"},
      {"# vtk DataFile Version 2.0\nt\nASCII\nDATASET POLYDATA\n",
       "soft.vtk: line 4: a soft body's file must be 'DATASET UNSTRUCTURED_GRID'"},
      {head + "POINTS 4 double\n0 0 0\n1 0 zero\n", "soft.vtk: line 7: 'zero' is not a number (a point's z)"},
      {head + "POINTS 4 double\n0 0 0\n1 0\n", "soft.vtk: line 8: the file ends where a point's z should be"},
      {head + "POINTS 9000000000 double\n", "soft.vtk: line 5: the point count 9000000000 is out of range [0, 14]"},
      {head + points, "soft.vtk: no CELLS section (a volume needs POINTS and CELLS)"},
      {head + points + "CELLS 2 9\n4 0 1 2 3\n3 0 1 2\n",
       "soft.vtk: cell 1 has 3 nodes and the file gives no CELL_TYPES (without them, every cell must be a "
       "tetrahedron)"},
      {head + points + "POLYGONS 1 5\n",
       "soft.vtk: line 10: unknown section 'POLYGONS' (POINTS, CELLS and CELL_TYPES make a volume)"},
      {head + points + "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 2\n10\n10\n",
       "soft.vtk: CELL_TYPES lists 2 types for 1 cells"},
      {head + points + "CELLS 1 5\n4 0 1 2 7\nCELL_TYPES 1\n10\n",
       "soft.vtk: cell 0 names point 7, but the file has 4 points"},
      {head + points + "CELLS 1 5\n3 0 1 2\nCELL_TYPES 1\n10\n",
       "soft.vtk: cell 0 is a tetrahedron (type 10) of 3 nodes"},
      {head + points + "CELLS 1 9\n8 0 1 2 3 0 1 2 3\nCELL_TYPES 1\n12\n",
       "soft.vtk: cell 0 has type 12 (a hexahedron): a soft body's volume must be linear tetrahedra (type 10)"},
      {head + points + "CELLS 1 5\n3 0 1 2\nCELL_TYPES 1\n5\n",
       "soft.vtk: no tetrahedra: a soft body needs a volume mesh"},
      {head + "POINTS 4 double\n0 0 0\n1 0 0\n0 1 0\nnan 0 1\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n",
       "soft.vtk: node 3 is not finite (nan 0 1)"},
      {head + "POINTS 4 double\n0 0 0\n1 0 0\n0 1 0\n1 1 0\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n",
       "soft.vtk: tetrahedron 0 is degenerate: 6 V / L^3 = 0 (flat or a sliver; at least 1e-06)"},
      {head + points + "CELLS 1 5\n4 0 1 1 3\nCELL_TYPES 1\n10\n", "soft.vtk: tetrahedron 0 names node 1 twice"},
      {head + "POINTS 5 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\nCELLS 3 15\n4 0 1 2 3\n4 0 2 1 3\n4 1 4 2 3\n"
              "CELL_TYPES 3\n10\n10\n10\n",
       "soft.vtk: tetrahedron 1 is inverted: its volume's sign is opposite to that of 2 of the mesh's 3 tetrahedra "
       "(the mesh folds over itself)"},
      // Both tetrahedra positive, on the same side of face (0 2 3): found by soft_loading_fuzz.
      {head + "POINTS 5 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\nCELLS 2 10\n4 0 1 2 3\n4 0 4 2 3\n"
              "CELL_TYPES 2\n10\n10\n",
       "soft.vtk: tetrahedra 0 and 1 overlap: both lie on the same side of their face (0 2 3)"},
      {head + "POINTS 6 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n-1 -1 2\nCELLS 3 15\n4 0 1 2 3\n"
              "4 1 4 2 3\n4 1 2 5 3\nCELL_TYPES 3\n10\n10\n10\n",
       "soft.vtk: face (1 2 3) is shared by 3 tetrahedra (0, 1, 2): a face bounds at most two"},
  };
  for (const auto& [text, expected] : cases)
  {
    EXPECT_EQ(errorOf(text), expected) << text;
  }
}

TEST(VtkTetReader, RefusesWhatIsNotARegularFile)
{
  try
  {
    readVtkTetMesh("/dev/zero");
    FAIL();
  }
  catch (const InputError& error)
  {
    EXPECT_STREQ(error.what(), "soft body file '/dev/zero' does not exist or is not a regular file");
  }
}

TEST(TetMesh, TheBlocksSurfaceIsClosedAndFacesOut)
{
  BlockMeshSpec spec;
  spec.size = Eigen::Vector3d(0.2, 0.1, 0.05);
  spec.cells = {4, 3, 2};
  spec.grading = 2.0;
  const TetMesh mesh = blockTetMesh(spec);
  EXPECT_EQ(mesh.nodes.size(), 5u * 4u * 3u);
  EXPECT_EQ(mesh.tets.size(), 6u * 24u);
  const auto surface = surfaceTriangles(mesh);
  EXPECT_EQ(surface.size(), 2u * (2u * (4 * 3 + 4 * 2 + 3 * 2)));
  // Closed: every directed edge once, and its reverse once. Outward: the divergence theorem's
  // volume, sum of (centroid . normal) area / 3, is the block's.
  std::map<std::pair<int, int>, int> edges;
  double volume = 0.0;
  for (const auto& face : surface)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++edges[{face[k], face[(k + 1) % 3]}];
    }
    const Eigen::Vector3d& a = mesh.nodes[face[0]];
    const Eigen::Vector3d& b = mesh.nodes[face[1]];
    const Eigen::Vector3d& c = mesh.nodes[face[2]];
    volume += a.dot(b.cross(c)) / 6.0;
  }
  for (const auto& [edge, count] : edges)
  {
    ASSERT_EQ(count, 1);
    ASSERT_EQ(edges.count({edge.second, edge.first}), 1u);
  }
  EXPECT_NEAR(volume, 0.2 * 0.1 * 0.05, 1e-15);
}
}  // namespace
}  // namespace god_finger
