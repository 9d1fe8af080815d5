// A decomposition the user made is used as given: a closed mesh of convex pieces (V-HACD's hulls
// in one OBJ, here three boxes and a tetrahedron apart from one another) collides as exactly
// those pieces, never simplified or decomposed again; a mesh with one concave piece, or a single
// piece, is decomposed as before.
#include "god_finger/scene/convex_decomposition.h"

#include "god_finger/geometry/mesh_primitives.h"
#include "god_finger/mesh_io/mesh_loader.h"
#include "god_finger/mesh_io/mesh_writer.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/urdf_scene.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace god_finger
{
namespace
{
void append(const TriangleSoup& more, const Eigen::Vector3d& offset, TriangleSoup* soup)
{
  const int first = static_cast<int>(soup->vertices.size());
  for (const Eigen::Vector3d& vertex : more.vertices)
  {
    soup->vertices.push_back(vertex + offset);
  }
  for (const auto& triangle : more.triangles)
  {
    soup->triangles.push_back({triangle[0] + first, triangle[1] + first, triangle[2] + first});
  }
}

// Three 2 cm boxes 5 cm apart along x and a tetrahedron above the middle one: 4 convex pieces.
TriangleSoup pieces()
{
  TriangleSoup soup;
  for (const double x : {-0.05, 0.0, 0.05})
  {
    append(makeBox(Eigen::Vector3d(0.01, 0.01, 0.01)), Eigen::Vector3d(x, 0.0, 0.0), &soup);
  }
  TriangleSoup tetra;
  tetra.vertices = {{0, 0, 0}, {0.01, 0, 0}, {0, 0.01, 0}, {0, 0, 0.01}};
  tetra.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  append(tetra, Eigen::Vector3d(0.0, 0.0, 0.03), &soup);
  return soup;
}

TEST(GivenDecomposition, AMeshOfConvexPiecesIsItsOwnDecomposition)
{
  const TriangleMesh mesh = TriangleMesh::build(pieces());
  const std::optional<HullSet> given = givenConvexPieces(mesh);
  ASSERT_TRUE(given.has_value());
  ASSERT_EQ(given->size(), 4u);
  std::vector<std::size_t> corners;
  for (const std::vector<Eigen::Vector3d>& piece : *given)
  {
    corners.push_back(piece.size());
  }
  std::sort(corners.begin(), corners.end());
  EXPECT_EQ(corners, (std::vector<std::size_t>{4, 8, 8, 8}));
  const ConvexDecomposition decomposition = cachedConvexDecomposition(mesh, "'pieces'");
  EXPECT_EQ(decomposition.source, DecompositionSource::kGiven);
  EXPECT_EQ(decomposition.hulls->size(), 4u);
  EXPECT_STREQ(decompositionSourceName(DecompositionSource::kGiven), "as given");
}

TEST(GivenDecomposition, AConcavePieceOrASinglePieceIsNotGiven)
{
  TriangleSoup with_l = pieces();
  append(makeLBlock(0.01, 0.01), Eigen::Vector3d(0.0, 0.1, 0.0), &with_l);
  EXPECT_FALSE(givenConvexPieces(TriangleMesh::build(with_l)).has_value()) << "the L block is concave";
  EXPECT_FALSE(givenConvexPieces(TriangleMesh::build(makeBox(Eigen::Vector3d(0.01, 0.01, 0.01)))).has_value())
      << "one piece: a hull, not a decomposition";
  EXPECT_FALSE(givenConvexPieces(TriangleMesh::build(makeMug(0.04, 0.09, 0.005, 0.006, 24))).has_value())
      << "a cup and a ring handle: two concave pieces";
}

// As a free body on the table: it rests on its three boxes' bottoms exactly (the hulls are the
// boxes), and the scene tool's summary says the pieces were used as given.
TEST(GivenDecomposition, ABodyOfGivenPiecesCollidesAsExactlyThosePieces)
{
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "god_finger_given_pieces";
  std::filesystem::create_directories(folder);
  writeTriangleSoup(pieces(), (folder / "pieces.obj").string());
  const TriangleMesh loaded = loadTriangleMesh((folder / "pieces.obj").string());
  std::printf("given_decomposition: loaded %d vertices, %d triangles, %d components, %d boundary edges\n",
              loaded.vertexCount(), loaded.triangleCount(), loaded.health().components, loaded.health().boundary_edges);
  ASSERT_TRUE(givenConvexPieces(loaded).has_value()) << "the pieces survive the OBJ file";
  const std::string xml =
      "<?xml version='1.0'?><robot name='t'><link name='world'/>"
      "<link name='table'><collision><geometry><box size='1 1 0.04'/></geometry></collision></link>"
      "<joint name='tj' type='fixed'><parent link='world'/><child link='table'/><origin xyz='0 0 -0.02'/></joint>"
      "<link name='pieces'><inertial><mass value='0.1'/><inertia ixx='1e-5' ixy='0' ixz='0' iyy='1e-4' iyz='0' "
      "izz='1e-4'/></inertial><collision><geometry><mesh filename='pieces.obj'/></geometry></collision></link>"
      "<joint name='pj' type='floating'><parent link='world'/><child link='pieces'/><origin xyz='0 0 0.015'/></joint>"
      "</robot>";
  const SceneDescription scene = parseUrdfScene(xml, folder.string(), "pieces.urdf");
  GodFingerWorld world(scene, WorldParams());
  const int body = scene.find("pieces");
  const GodFingerWorld::BodyCollision collision = world.bodyCollision(body);
  EXPECT_EQ(collision.convex_hulls, 4);
  EXPECT_TRUE(collision.hulls_as_given);
  for (int i = 0; i < 1000; ++i)
  {
    world.step();
  }
  // The boxes' bottoms (1 cm below the link) on the table, within the 0.5 mm collision margins.
  EXPECT_NEAR(world.bodyState(body).pose.translation().z(), 0.01, 1.1e-3);
  EXPECT_LT(world.bodyState(body).linear_velocity.norm(), 1e-3);
  std::filesystem::remove_all(folder);
}
}  // namespace
}  // namespace god_finger
