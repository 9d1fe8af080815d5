// PyBullet-style <deformable> URDFs (deformable_object.h): the shipped soft block and a
// PyBullet-like torus load with their material; every bad file gets its one-line error; the
// scene loaders (URDF scene, object file, scene list) make each a static soft body.
#include "god_finger/scene/deformable_object.h"
#include "god_finger/scene/scene_file.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

namespace god_finger
{
namespace
{
const std::string kObjects = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/objects";

class DeformableTest : public ::testing::Test
{
 protected:
  DeformableTest()
  {
    std::string pattern = (std::filesystem::temp_directory_path() / "god_finger_soft_XXXXXX").string();
    folder_ = mkdtemp(pattern.data());
    write("tet.vtk",
          "# vtk DataFile Version 2.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n0 0 0\n0.1 0 0\n"
          "0 0.1 0\n0 0 0.1\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n");
  }
  ~DeformableTest() override
  {
    std::filesystem::remove_all(folder_);
  }

  std::string write(const std::string& name, const std::string& text) const
  {
    const std::string path = folder_ + "/" + name;
    std::ofstream(path) << text;
    return path;
  }

  std::string urdf(const std::string& inside) const
  {
    return write("soft.urdf", "<robot name=\"r\">\n<deformable name=\"d\">\n" + inside + "</deformable>\n</robot>\n");
  }

  std::string refusal(const std::string& inside) const
  {
    try
    {
      loadDeformables(urdf(inside));
    }
    catch (const InputError& error)
    {
      // The file's name leads every message about the URDF; the rest is what this test checks.
      const std::string prefix = "URDF '" + folder_ + "/soft.urdf': ";
      const std::string message = error.what();
      return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
    }
    return "no error";
  }

  std::string folder_;
};

TEST_F(DeformableTest, TheShippedSoftBlockLoadsWithItsMaterial)
{
  const std::vector<DeformableDescription> bodies = loadDeformables(kObjects + "/soft_block.urdf");
  ASSERT_EQ(bodies.size(), 1u);
  const DeformableDescription& block = bodies.front();
  EXPECT_EQ(block.name, "soft_block");
  EXPECT_EQ(block.model, "neohookean");
  EXPECT_EQ(block.mesh.nodes.size(), 1000u);
  EXPECT_EQ(block.mesh.tets.size(), 4374u);
  EXPECT_NEAR(block.material.young_modulus, 50e3, 1e-9);
  EXPECT_NEAR(block.material.poisson_ratio, 0.45, 1e-15);
  EXPECT_NEAR(block.material.density, 1000.0, 1e-9);
  EXPECT_EQ(block.material.stiffness_damping, 0.01);
  EXPECT_EQ(block.friction, 0.8);
  EXPECT_EQ(block.collision_margin, 0.001);
}

TEST_F(DeformableTest, TheShippedSoftBallRestsFreeAndTheBlockIsGlued)
{
  const std::vector<DeformableDescription> balls = loadDeformables(kObjects + "/soft_ball.urdf");
  ASSERT_EQ(balls.size(), 1u);
  EXPECT_TRUE(balls[0].resting);
  EXPECT_EQ(balls[0].mesh.nodes.size(), 729u);
  EXPECT_NEAR(balls[0].material.young_modulus, 100e3, 1e-6);
  EXPECT_NEAR(balls[0].mass, 0.1, 1e-15);
  EXPECT_FALSE(loadDeformables(kObjects + "/soft_block.urdf")[0].resting);
}

TEST_F(DeformableTest, APyBulletTorusLikeFileLoads)
{
  // PyBullet's deformable_torus.urdf's values: mu 60, lambda 200 (Pa), damping 0.01, mass 1.
  const std::string path = urdf(
      "<inertial><mass value=\"1\"/><inertia ixx=\"0.0\" ixy=\"0\" ixz=\"0\" iyy=\"0\" iyz=\"0\" "
      "izz=\"0\"/></inertial>\n"
      "<collision_margin value=\"0.006\"/><repulsion_stiffness value=\"800.0\"/><friction value= \"0.5\"/>\n"
      "<neohookean mu= \"60\" lambda= \"200\" damping= \"0.01\" />\n<visual filename=\"tet.vtk\"/>\n");
  const std::vector<DeformableDescription> bodies = loadDeformables(path);
  ASSERT_EQ(bodies.size(), 1u);
  EXPECT_NEAR(bodies[0].material.young_modulus, 60.0 * (3 * 200 + 2 * 60) / 260.0, 1e-12);
  EXPECT_NEAR(bodies[0].material.poisson_ratio, 200.0 / 520.0, 1e-15);
  EXPECT_NEAR(bodies[0].material.density, 1.0 / (0.001 / 6.0), 1e-6);
  EXPECT_EQ(bodies[0].volume_file, folder_ + "/tet.vtk");
  EXPECT_EQ(bodies[0].friction, 0.5);
}

TEST_F(DeformableTest, EachBadFileGetsItsOneLineError)
{
  const std::string mass = "<inertial><mass value=\"1\"/></inertial>\n";
  const std::string material = "<neohookean mu=\"1000\" lambda=\"4000\"/>\n";
  const std::string volume = "<collision filename=\"tet.vtk\"/>\n";
  const std::map<std::string, std::string> cases = {
      {mass + "<neohooken mu=\"1000\" lambda=\"4000\"/>\n" + volume,
       "deformable 'd' (line 4): unknown element <neohooken> (a deformable has inertial, neohookean or corotated, "
       "collision, visual, friction, collision_margin, origin, support)"},
      {mass + material + volume + "<support value=\"free\"/>\n",
       "deformable 'd' (line 6): <support value> is 'free': give glued or resting"},
      {mass + material + volume + "<support/>\n",
       "deformable 'd' (line 6): <support value> is '': give glued or resting"},
      {mass + material + volume + "<origin xyz=\"0 0\"/>\n",
       "deformable 'd' (line 6): <origin xyz> '0 0' is not three finite numbers"},
      {mass + material + volume + "<origin xyz=\"0 0 0\" rpy=\"0 inf 0\"/>\n",
       "deformable 'd' (line 6): <origin rpy> '0 inf 0' is not three finite numbers"},
      {mass + material + volume + "<origin xyz=\"0 0 0 1\"/>\n",
       "deformable 'd' (line 6): <origin xyz> '0 0 0 1' is not three finite numbers"},
      {mass + "<spring elastic_stiffness=\"1\"/>\n" + volume,
       "deformable 'd' (line 2): mass-spring deformables (<spring> alone) are not modelled: give <neohookean mu "
       "lambda> or <corotated mu lambda>"},
      {mass + volume,
       "deformable 'd' (line 2): no material: give <neohookean mu lambda [damping]> or <corotated mu "
       "lambda [damping]>"},
      {material + volume, "deformable 'd' (line 2): needs <inertial><mass value> > 0 (kg)"},
      {mass + "<neohookean mu=\"-5\" lambda=\"4000\"/>\n" + volume,
       "deformable 'd' (line 4): mu = -5 and lambda = 4e+03 must be > 0 and >= 0 (Pa)"},
      {mass + "<neohookean mu=\"1000\" lambda=\"nan\"/>\n" + volume,
       "deformable 'd' (line 4): <neohookean lambda> 'nan' is not a finite number"},
      {mass + "<neohookean mu=\"1000\" lambda=\"1e9\"/>\n" + volume,
       "deformable 'd': poisson_ratio = 0.5 is out of range [0, 0.49]"},
      {mass + material,
       "deformable 'd' (line 2): needs <collision filename> or <visual filename> naming its "
       "tetrahedral .vtk volume"},
      {mass + material + "<collision filename=\"torus.obj\"/>\n",
       "deformable 'd' (line 5): 'torus.obj' is not a .vtk volume: a surface mesh would have to be filled with "
       "tetrahedra first (TetWild, gmsh), which the loader does not do"},
      {mass + material + "<collision filename=\"package://nowhere_pkg/ball.vtk\"/>\n",
       "deformable 'd' (line 5): package 'nowhere_pkg' of 'package://nowhere_pkg/ball.vtk' is not known"},
  };
  for (const auto& [inside, expected] : cases)
  {
    EXPECT_EQ(refusal(inside), expected) << inside;
  }
  EXPECT_EQ(refusal(mass + material + "<collision filename=\"missing.vtk\"/>\n"),
            "soft body file '" + folder_ + "/missing.vtk' does not exist or is not a regular file");
}

TEST_F(DeformableTest, ScenesHoldSoftBodiesWhereTheirOriginAndPlacementPutThem)
{
  // PyBullet's object file alone: one static body, its volume named, its friction kept.
  const SceneDescription object = loadScene(kObjects + "/soft_block.urdf");
  ASSERT_EQ(object.bodies.size(), 1u);
  const BodyDescription& block = object.bodies.front();
  EXPECT_EQ(block.name, "soft_block");
  ASSERT_TRUE(block.soft);
  EXPECT_TRUE(block.is_static);
  EXPECT_EQ(block.geometry.kind, GeometryKind::kMesh);
  EXPECT_EQ(block.geometry.mesh_path, kObjects + "/soft_block.vtk");
  EXPECT_EQ(block.material.friction, 0.8);
  EXPECT_TRUE(block.pose.isApprox(Eigen::Isometry3d::Identity(), 0.0));
  // A scene URDF: a table link and a deformable at its <origin>.
  const std::string scene_path =
      write("scene.urdf",
            "<robot name=\"s\"><link name=\"world\"/>\n"
            "<link name=\"table\"><collision><geometry><box size=\"1 1 0.04\"/></geometry></collision></link>\n"
            "<joint name=\"j\" type=\"fixed\"><parent link=\"world\"/><child link=\"table\"/>"
            "<origin xyz=\"0 0 -0.02\"/></joint>\n"
            "<deformable name=\"pad\"><inertial><mass value=\"0.1\"/></inertial>"
            "<neohookean mu=\"1000\" lambda=\"4000\"/><collision filename=\"tet.vtk\"/>"
            "<origin xyz=\"0.1 0.2 0\" rpy=\"0 0 1.5707963267948966\"/></deformable>\n</robot>\n");
  const SceneDescription scene = loadScene(scene_path);
  ASSERT_EQ(scene.bodies.size(), 2u);
  EXPECT_EQ(scene.bodies[0].name, "table");
  EXPECT_FALSE(scene.bodies[0].soft);
  EXPECT_EQ(scene.bodies[1].name, "pad");
  ASSERT_TRUE(scene.bodies[1].soft);
  EXPECT_TRUE(scene.bodies[1].pose.translation().isApprox(Eigen::Vector3d(0.1, 0.2, 0.0), 1e-15));
  EXPECT_NEAR((scene.bodies[1].pose * Eigen::Vector3d::UnitX()).y(), 0.2 + 1.0, 1e-12);
  // A scene list places it; it cannot be made free.
  const std::string list =
      write("list.yaml", "objects:\n  - file: " + kObjects + "/soft_block.urdf\n    xyz: [0.0, 0.0, 0.0]\n");
  const SceneDescription listed = loadScene(list);
  ASSERT_EQ(listed.bodies.size(), 2u);  // the table, the block
  EXPECT_TRUE(listed.bodies[1].soft);
  const std::string freed =
      write("free.yaml", "objects:\n  - file: " + kObjects + "/soft_block.urdf\n    fixed: false\n");
  try
  {
    loadScene(freed);
    FAIL() << "no error";
  }
  catch (const InputError& error)
  {
    EXPECT_NE(std::string(error.what())
                  .find("body 'soft_block' is a soft body: it is glued by its lowest nodes to what it "
                        "rests on, and cannot be made free (fixed: false)"),
              std::string::npos)
        << error.what();
  }
}
}  // namespace
}  // namespace god_finger
