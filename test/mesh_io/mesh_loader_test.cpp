// Mesh files: every format round-trips through our writers and assimp, scale is applied, and
// every bad file gives one clear error naming the file.
#include "god_finger/mesh_io/mesh_loader.h"
#include "god_finger/support/input_error.h"
#include "god_finger/geometry/mesh_primitives.h"
#include "god_finger/mesh_io/mesh_writer.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace god_finger
{
namespace
{
std::string temporaryPath(const std::string& name)
{
  return ::testing::TempDir() + "god_finger_" + name;
}

void writeFile(const std::string& path, const std::string& content)
{
  std::ofstream(path) << content;
}

// The error message of loading `path`, or "" when it loads.
std::string loadError(const std::string& path)
{
  try
  {
    loadTriangleSoup(path);
  }
  catch (const InputError& error)
  {
    return error.what();
  }
  return std::string();
}

TEST(MeshLoader, EveryFormatRoundTrips)
{
  const TriangleSoup original = makeTorus(0.06, 0.02, 12, 8);
  const TriangleMesh expected = TriangleMesh::build(original);
  for (const std::string extension : {"stl", "obj", "off", "ply", "dae"})
  {
    const std::string path = temporaryPath("round_trip." + extension);
    writeTriangleSoup(original, path);
    const TriangleMesh loaded = loadTriangleMesh(path);
    EXPECT_EQ(loaded.triangleCount(), expected.triangleCount()) << extension;
    EXPECT_EQ(loaded.vertexCount(), expected.vertexCount()) << extension;
    EXPECT_EQ(loaded.health().boundary_edges, 0) << extension;
    EXPECT_EQ(loaded.health().flipped_triangles, 0) << extension;
    // assimp stores coordinates as 32-bit floats: 6e-8 relative, i.e. 5e-9 m here.
    double worst = 0.0;
    for (int t = 0; t < loaded.triangleCount(); ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        worst = std::max(worst, (loaded.corner(t, k) - expected.corner(t, k)).norm());
      }
      EXPECT_EQ(loaded.sourceTriangle(t), t);
    }
    EXPECT_LT(worst, 1e-8) << extension;
    std::remove(path.c_str());
  }
}

TEST(MeshLoader, ScaleIsApplied)
{
  const std::string path = temporaryPath("scaled.obj");
  writeTriangleSoup(makeBox(Eigen::Vector3d(0.5, 0.5, 0.5)), path);
  const TriangleSoup soup = loadTriangleSoup(path, Eigen::Vector3d(2.0, 3.0, -4.0));
  Eigen::Vector3d lower = Eigen::Vector3d::Constant(1e9);
  Eigen::Vector3d upper = -lower;
  for (const Eigen::Vector3d& v : soup.vertices)
  {
    lower = lower.cwiseMin(v);
    upper = upper.cwiseMax(v);
  }
  EXPECT_EQ(lower, Eigen::Vector3d(-1.0, -1.5, -2.0));
  EXPECT_EQ(upper, Eigen::Vector3d(1.0, 1.5, 2.0));
  // A mirroring scale turns the mesh inside out; the builder turns it back outward.
  const TriangleMesh mesh = loadTriangleMesh(path, Eigen::Vector3d(2.0, 3.0, -4.0));
  EXPECT_EQ(mesh.health().flipped_triangles, 12);
  EXPECT_THROW(loadTriangleSoup(path, Eigen::Vector3d(1.0, 0.0, 1.0)), InputError);
  std::remove(path.c_str());
}

TEST(MeshLoader, BadFilesGiveOneClearError)
{
  EXPECT_EQ(loadError("/nonexistent/box.stl"), "mesh file '/nonexistent/box.stl': no such file or not readable");

  const std::string empty = temporaryPath("empty.stl");
  writeFile(empty, "");
  EXPECT_EQ(loadError(empty).rfind("mesh file '" + empty + "': unreadable: ", 0), 0u) << loadError(empty);

  const std::string garbage = temporaryPath("garbage.ply");
  writeFile(garbage, "this is not a mesh\n\x01\x02\x03 at all\n");  // not even a PLY header
  EXPECT_EQ(loadError(garbage).rfind("mesh file '" + garbage + "': unreadable: ", 0), 0u) << loadError(garbage);

  const std::string lines = temporaryPath("lines.obj");
  writeFile(lines, "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n");
  EXPECT_EQ(loadError(lines), "mesh file '" + lines + "': has no triangles");

  const std::string flat = temporaryPath("degenerate.off");
  writeFile(flat, "OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n");
  try
  {
    loadTriangleMesh(flat);
    ADD_FAILURE() << "no error for a file of degenerate triangles";
  }
  catch (const InputError& error)
  {
    EXPECT_EQ(std::string(error.what()).rfind("mesh file '" + flat + "': no non-degenerate triangles", 0), 0u)
        << error.what();
  }
  for (const std::string& path : {empty, garbage, lines, flat})
  {
    std::remove(path.c_str());
  }
}

TEST(MeshLoader, ShippedMeshesAreClosedAndManifold)
{
  for (const std::string name : {"box.stl", "sphere.obj", "cylinder.ply", "torus.dae", "l_block.off"})
  {
    const TriangleMesh mesh = loadTriangleMesh(std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/meshes/" + name);
    EXPECT_EQ(mesh.health().boundary_edges, 0) << name;
    EXPECT_EQ(mesh.health().non_manifold_edges, 0) << name;
    EXPECT_EQ(mesh.health().flipped_triangles, 0) << name;
    EXPECT_EQ(mesh.health().components, 1) << name;
  }
}
TEST(MeshLoader, FuzzFoundFilesGiveAnErrorNotACrashOrAHang)
{
  // Inputs kept by test/fuzz/mesh_loading_fuzz (first byte: the extension, as the target
  // reads them): OFF files on which assimp's triangulation aborted the process, PLY headers on
  // which assimp looped forever, STL/PLY files on which it leaks (upstream). Each must now load
  // or give InputError naming the file, at once.
  const std::filesystem::path kept =
      std::filesystem::path(GOD_FINGER_SOURCE_DIR) / "test/fuzz/regressions/mesh_loading_fuzz";
  const char* const extensions[] = {"stl", "obj", "ply", "off"};
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kept))
  {
    std::ifstream in(entry.path(), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_FALSE(bytes.empty()) << entry.path();
    const std::string path = std::string(::testing::TempDir()) + "fuzz_kept." + extensions[bytes[0] % 4];
    std::ofstream(path, std::ios::binary) << bytes.substr(1);
    try
    {
      loadTriangleMesh(path);
    }
    catch (const InputError& error)
    {
      EXPECT_NE(std::string(error.what()).find("mesh file '" + path + "'"), std::string::npos) << error.what();
    }
    std::remove(path.c_str());
    ++files;
  }
  EXPECT_GE(files, 3);
}
}  // namespace
}  // namespace god_finger

namespace god_finger
{
namespace
{
// One triangle at height z = 1 in a COLLADA file of the given up axis and unit.
std::string colladaTriangle(const std::string& up_axis, double metres_per_unit)
{
  return "<?xml version=\"1.0\"?>\n<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" "
         "version=\"1.4.1\"><asset><unit meter=\"" +
         std::to_string(metres_per_unit) + "\"/><up_axis>" + up_axis +
         "</up_axis></asset><library_geometries><geometry id=\"g\"><mesh><source id=\"p\"><float_array id=\"pa\" "
         "count=\"9\">0 0 1 1 0 1 0 1 1</float_array><technique_common><accessor source=\"#pa\" count=\"3\" "
         "stride=\"3\"><param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/><param name=\"Z\" "
         "type=\"float\"/></accessor></technique_common></source><vertices id=\"v\"><input semantic=\"POSITION\" "
         "source=\"#p\"/></vertices><triangles count=\"1\"><input semantic=\"VERTEX\" source=\"#v\" "
         "offset=\"0\"/><p>0 1 2</p></triangles></mesh></geometry></library_geometries><library_visual_scenes>"
         "<visual_scene id=\"s\"><node id=\"n\"><instance_geometry url=\"#g\"/></node></visual_scene>"
         "</library_visual_scenes><scene><instance_visual_scene url=\"#s\"/></scene></COLLADA>\n";
}

TEST(MeshLoader, ColladaIsReadAsRvizShowsIt)
{
  // rviz (and Gazebo, MoveIt) ignore the up-axis conversion assimp puts on the root node and
  // apply <unit>: the physics must collide with what the user sees.
  const std::string path = temporaryPath("up_axis.dae");
  for (const std::string up_axis : {"Z_UP", "Y_UP"})
  {
    for (const double unit : {1.0, 0.01})
    {
      writeFile(path, colladaTriangle(up_axis, unit));
      const TriangleSoup soup = loadTriangleSoup(path);
      ASSERT_EQ(soup.triangles.size(), 1u);
      const Eigen::Vector3d expected[] = {{0, 0, unit}, {unit, 0, unit}, {0, unit, unit}};
      for (int k = 0; k < 3; ++k)
      {
        EXPECT_LT((soup.vertices[soup.triangles[0][k]] - expected[k]).norm(), 1e-7 * unit)
            << up_axis << " unit " << unit << " corner " << k << ": "
            << soup.vertices[soup.triangles[0][k]].transpose();
      }
    }
  }
  std::remove(path.c_str());
}
}  // namespace
}  // namespace god_finger
