// The one scene loader: URDF scenes and object files by their URDF, scene lists (YAML) placing
// object files of their own on a table; every bad list refused with one line naming the list,
// the entry and the problem.
#include "god_finger/scene/scene_file.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace god_finger
{
namespace
{
const std::string kScenes = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes";

class SceneFiles : public ::testing::Test
{
 protected:
  void SetUp() override
  {
    folder_ = std::filesystem::temp_directory_path() /
              ("god_finger_scene_file_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(folder_);
    std::filesystem::create_directories(folder_ / "objects");
    // Object files as PyBullet ships them: the root link is the body.
    write("objects/ball.urdf",
          "<robot name='ball'><link name='baseLink'><contact><lateral_friction value='0.9'/></contact>"
          "<inertial><mass value='0.05'/><inertia ixx='1e-5' ixy='0' ixz='0' iyy='1e-5' iyz='0' izz='1e-5'/>"
          "</inertial><collision><geometry><sphere radius='0.02'/></geometry></collision></link></robot>");
    write("objects/block.urdf",
          "<robot name='block'><link name='baseLink'><inertial><mass value='0'/>"
          "<inertia ixx='0' ixy='0' ixz='0' iyy='0' iyz='0' izz='0'/></inertial>"
          "<collision><geometry><box size='0.1 0.05 0.02'/></geometry></collision></link></robot>");
  }
  void TearDown() override
  {
    std::filesystem::remove_all(folder_);
  }

  std::string write(const std::string& name, const std::string& text)
  {
    std::ofstream(folder_ / name) << text;
    return (folder_ / name).string();
  }

  std::string errorOf(const std::string& list_text)
  {
    try
    {
      loadScene(write("list.yaml", list_text));
    }
    catch (const InputError& error)
    {
      return error.what();
    }
    return "";
  }

  std::filesystem::path folder_;
};

TEST_F(SceneFiles, AListPlacesObjectFilesOnTheTable)
{
  const SceneDescription scene = loadScene(write("list.yaml",
                                                 "objects:\n"
                                                 "  - file: objects/ball.urdf\n"
                                                 "    xyz: [0.1, 0.0, 0.02]\n"
                                                 "  - file: objects/ball.urdf\n"
                                                 "    name: second_ball\n"
                                                 "    xyz: [-0.1, 0.0, 0.02]\n"
                                                 "  - file: objects/block.urdf\n"
                                                 "    name: block\n"
                                                 "    xyz: [0.0, 0.2, 0.01]\n"
                                                 "    rpy: [0.0, 0.0, 1.5707963267948966]\n"));
  ASSERT_EQ(scene.bodies.size(), 4u);
  EXPECT_EQ(scene.bodies[0].name, "table");
  EXPECT_TRUE(scene.bodies[0].is_static);
  EXPECT_DOUBLE_EQ(scene.bodies[0].pose.translation().z() + 0.5 * scene.bodies[0].geometry.size.z(), 0.0);
  EXPECT_EQ(scene.bodies[1].name, "baseLink");  // the file's own name when none is given
  EXPECT_FALSE(scene.bodies[1].is_static);
  EXPECT_DOUBLE_EQ(scene.bodies[1].mass, 0.05);
  EXPECT_DOUBLE_EQ(scene.bodies[1].material.friction, 0.9);
  EXPECT_TRUE(scene.bodies[1].pose.translation().isApprox(Eigen::Vector3d(0.1, 0.0, 0.02)));
  EXPECT_EQ(scene.bodies[2].name, "second_ball");
  EXPECT_TRUE(scene.bodies[2].pose.translation().isApprox(Eigen::Vector3d(-0.1, 0.0, 0.02)));
  EXPECT_EQ(scene.bodies[3].name, "block");
  EXPECT_TRUE(scene.bodies[3].is_static) << "mass 0 in its file: fixed, as PyBullet reads it";
  // Turned a quarter about z: the block's x axis lies along world y.
  EXPECT_TRUE((scene.bodies[3].pose.linear() * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY(), 1e-12));
}

TEST_F(SceneFiles, FixedOverridesTheFileAndSupportNoneLeavesTheTableOut)
{
  const SceneDescription scene = loadScene(write("list.yaml",
                                                 "support: none\n"
                                                 "objects:\n"
                                                 "  - file: objects/ball.urdf\n"
                                                 "    fixed: true\n"));
  ASSERT_EQ(scene.bodies.size(), 1u);
  EXPECT_TRUE(scene.bodies[0].is_static);
  const std::string error = errorOf("objects:\n  - file: objects/block.urdf\n    fixed: false\n");
  EXPECT_NE(error.find("objects[0]: body 'baseLink' is fixed in its file and has no usable <inertial>"),
            std::string::npos)
      << error;
  // A body fixed by its file's joint but with a usable <inertial> can be freed by the list.
  write("objects/pinned.urdf",
        "<robot name='pinned'><link name='world'/><link name='cube'><inertial><mass value='0.2'/>"
        "<inertia ixx='1e-4' ixy='0' ixz='0' iyy='1e-4' iyz='0' izz='1e-4'/></inertial>"
        "<collision><geometry><box size='0.05 0.05 0.05'/></geometry></collision></link>"
        "<joint name='j' type='fixed'><parent link='world'/><child link='cube'/></joint></robot>");
  const SceneDescription freed =
      loadScene(write("list.yaml", "objects:\n  - file: objects/pinned.urdf\n    fixed: false\n"));
  ASSERT_EQ(freed.bodies.size(), 2u);
  EXPECT_FALSE(freed.bodies[1].is_static);
  EXPECT_DOUBLE_EQ(freed.bodies[1].mass, 0.2);
}

TEST_F(SceneFiles, AURDFSceneLoadsThroughTheSameLoader)
{
  const SceneDescription scene = loadScene(kScenes + "/table_ball.urdf");
  EXPECT_EQ(scene.bodies.size(), 2u);
  // A listed scene file's bodies are moved by its pose, named NAME/BODY.
  const SceneDescription listed =
      loadScene(write("list.yaml", "support: none\nobjects:\n  - file: " + kScenes +
                                       "/table_ball.urdf\n    name: left\n    xyz: [0, -1, 0]\n"));
  ASSERT_EQ(listed.bodies.size(), 2u);
  EXPECT_EQ(listed.bodies[1].name, "left/" + scene.bodies[1].name);
  EXPECT_TRUE(
      listed.bodies[1].pose.translation().isApprox(scene.bodies[1].pose.translation() + Eigen::Vector3d(0, -1, 0)));
}

TEST_F(SceneFiles, AVisualMeshThatCannotBeUsedIsAWarningNotARefusal)
{
  write("objects/shown.urdf",
        "<robot name='shown'><link name='thing'><visual><geometry><mesh filename='not_here.dae'/></geometry></visual>"
        "<collision><geometry><sphere radius='0.02'/></geometry></collision></link></robot>");
  write("objects/two_visuals.urdf",
        "<robot name='two'><link name='thing'><visual><geometry><mesh filename='a.obj'/></geometry></visual>"
        "<visual><geometry><mesh filename='b.obj'/></geometry></visual>"
        "<collision><geometry><sphere radius='0.02'/></geometry></collision></link></robot>");
  const SceneDescription scene = loadScene(write("list.yaml",
                                                 "objects:\n  - file: objects/shown.urdf\n"
                                                 "  - file: objects/two_visuals.urdf\n    name: two\n"));
  ASSERT_EQ(scene.bodies.size(), 3u);
  EXPECT_FALSE(scene.bodies[1].visual_mesh.has_value());
  EXPECT_FALSE(scene.bodies[2].visual_mesh.has_value());
  ASSERT_EQ(scene.warnings.size(), 2u);
  EXPECT_NE(scene.warnings[0].find("link 'thing': its visual mesh cannot be used, the pad walks on its collision "
                                   "geometry"),
            std::string::npos)
      << scene.warnings[0];
  EXPECT_NE(scene.warnings[0].find("not_here.dae"), std::string::npos) << scene.warnings[0];
  EXPECT_NE(scene.warnings[1].find("2 visual meshes"), std::string::npos) << scene.warnings[1];
}

TEST_F(SceneFiles, TheShippedListLoadsItsObjectFiles)
{
  const SceneDescription scene = loadScene(std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/lists/table_objects.yaml");
  ASSERT_EQ(scene.bodies.size(), 6u);
  EXPECT_EQ(scene.bodies[0].name, "table");
  EXPECT_EQ(scene.bodies[1].name, "ball");
  EXPECT_EQ(scene.bodies[2].name, "mug");
  EXPECT_EQ(scene.bodies[2].geometry.kind, GeometryKind::kMesh);
  EXPECT_TRUE(std::filesystem::exists(scene.bodies[2].geometry.mesh_path)) << scene.bodies[2].geometry.mesh_path;
  EXPECT_FALSE(scene.bodies[3].is_static);
  EXPECT_TRUE(scene.bodies[4].is_static);
  EXPECT_EQ(scene.bodies[5].name, "stool");
  EXPECT_EQ(scene.bodies[5].more_parts.size(), 4u) << "a seat and four legs: one compound body";
}

TEST_F(SceneFiles, EveryBadListIsRefusedNamingItsProblem)
{
  const struct
  {
    std::string list;
    std::string expected;
  } cases[] = {
      {"objects: [", "line "},
      {"- a\n- b\n", "must be a map with 'objects'"},
      {"objects: []\n", "objects: must be a non-empty list"},
      {"support: floor\nobjects:\n  - file: objects/ball.urdf\n", "support: 'floor' is not one of table, none"},
      {"objetcs:\n  - file: objects/ball.urdf\n", "unknown key 'objetcs' (known: objects, support)"},
      {"objects:\n  - fiel: objects/ball.urdf\n",
       "objects[0]: unknown key 'fiel' (known: file, fixed, name, rpy, xyz)"},
      {"objects:\n  - name: x\n", "objects[0]: has no 'file'"},
      {"objects:\n  - file: objects/nothing.urdf\n", "objects[0]: URDF '"},
      {"objects:\n  - file: objects/ball.urdf\n    xyz: [0, 1]\n", "objects[0].xyz: must be three finite numbers"},
      {"objects:\n  - file: objects/ball.urdf\n    xyz: [0, .nan, 1]\n", "objects[0].xyz: must be three finite"},
      {"objects:\n  - file: objects/ball.urdf\n    rpy: [a, b, c]\n", "objects[0].rpy: must be three finite"},
      {"objects:\n  - file: objects/ball.urdf\n    fixed: maybe\n", "objects[0].fixed: must be true or false"},
      {"objects:\n  - file: objects/ball.urdf\n  - file: objects/ball.urdf\n",
       "objects[1]: the name 'baseLink' is given twice"},
      {"objects:\n  - file: objects/ball.urdf\n    name: table\n", "objects[0]: the name 'table' is given twice"},
      {"objects:\n  - file: list.yaml\n", "a scene list cannot list another"},
      {"objects:\n  - file: package://no_such_package/ball.urdf\n", "ROS package 'no_such_package' not found"},
      // Found by scene_loading_fuzz: a list as a key threw yaml-cpp's own exception past the loader.
      {"[a]: 1\nobjects:\n  - file: objects/ball.urdf\n", "unknown key '(not a text)'"},
      {"objects:\n  - file: [a, b]\n", "objects[0].file: must be a text"},
  };
  for (const auto& bad : cases)
  {
    const std::string error = errorOf(bad.list);
    EXPECT_EQ(error.rfind("scene list '", 0), 0u) << bad.list << " -> " << error;
    EXPECT_NE(error.find(bad.expected), std::string::npos) << bad.list << " -> " << error;
  }
  try
  {
    loadScene((folder_ / "missing.yaml").string());
    ADD_FAILURE() << "a missing list loaded";
  }
  catch (const InputError& error)
  {
    EXPECT_NE(std::string(error.what()).find("missing.yaml': no such file or not readable"), std::string::npos)
        << error.what();
  }
}
}  // namespace
}  // namespace god_finger
