// god_finger_scene as a user runs it: the shipped scene list's summary (bodies, the surface each
// pad walks on), a touch on its ball (an area, a force, the ball held by the table) and on its
// hollow mug (the finger on its inner floor), and one
// line and exit code 2 for a scene that cannot be used or a body that is not there.
#include "tool_run.h"

#include <gtest/gtest.h>

#include <string>

namespace god_finger
{
namespace
{
const std::string kList = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/lists/table_objects.yaml";

TEST(SceneTool, SummarisesTheShippedListsBodies)
{
  const test::ToolRun run = test::runTool(GOD_FINGER_SCENE_TOOL, kList);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("6 bodies"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("table            fixed"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("ball             free  0.200 kg at (0.000, 0.000, 0.040) m; collides as sphere; the pad "
                         "walks on it"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("stool            free  0.150 kg at (-0.120, -0.100, 0.001) m; collides as box + box + box + "
                         "box + box; the pad walks on all its pieces, 60 triangles"),
            std::string::npos)
      << run.out;
}

TEST(SceneTool, FindsTheListsPackageFilesFromARelativePathAsTypedInThePackage)
{
  const test::ToolRun run = test::runTool(std::string("cd ") + GOD_FINGER_SOURCE_DIR + " && " + GOD_FINGER_SCENE_TOOL,
                                          "urdf/lists/table_objects.yaml");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("6 bodies"), std::string::npos) << run.out;
}

TEST(SceneTool, TouchesABodyAndReportsTheAreaAndTheForce)
{
  const test::ToolRun run = test::runTool(GOD_FINGER_SCENE_TOOL, kList + " --touch ball");
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_NE(
      run.out.find("touch 'ball': a finger down over its centre, to 5 mm below its surface there (0.0000, 0.0000, "
                   "0.0800) m"),
      std::string::npos)
      << run.out;
  const std::size_t radius = run.out.find("contact area: radius ");
  ASSERT_NE(radius, std::string::npos) << run.out;
  EXPECT_GT(std::stod(run.out.substr(radius + 21)), 2.0) << "a pad of a few mm, not a point: " << run.out;
  const std::size_t force = run.out.find("force on the hand: ");
  ASSERT_NE(force, std::string::npos) << run.out;
  EXPECT_GT(std::stod(run.out.substr(force + 19)), 1.0) << run.out;
}

// The mug is hollow: the finger comes down over its rim into it and presses its inner floor
// (6 mm above its base, which rests 0.5 mm above the table), not a lid over the opening at the
// rim's 9 cm.
TEST(SceneTool, TouchesTheMugsInnerFloor)
{
  const test::ToolRun run = test::runTool(GOD_FINGER_SCENE_TOOL, kList + " --touch mug");
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("convex hulls); fingers touch its true surface; the pad walks on it"), std::string::npos)
      << run.out;
  const std::size_t stopped = run.out.find("the finger (its god-object) stopped at z ");
  ASSERT_NE(stopped, std::string::npos) << run.out;
  const double z = std::stod(run.out.substr(stopped + 41));
  // The god-object's centre: its 3 mm radius above the 6.5 mm floor, within Bullet's margins.
  EXPECT_NEAR(z, 0.0065 + 0.003, 1.5e-3) << run.out;
  const std::size_t force = run.out.find("force on the hand: ");
  ASSERT_NE(force, std::string::npos) << run.out;
  EXPECT_GT(std::stod(run.out.substr(force + 19)), 1.0) << "the floor holds the finger up: " << run.out;
}

TEST(SceneTool, TouchesASoftBlockAndReportsItsDimple)
{
  const test::ToolRun run = test::runTool(
      GOD_FINGER_SCENE_TOOL, std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes/soft_block.urdf --touch soft_block");
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("soft_block       fixed soft (1000 nodes, 4374 tetrahedra, E 50 kPa, nu 0.45, 1 kg, glued "
                         "where it rests)"),
            std::string::npos)
      << run.out;
  const std::size_t sank = run.out.find("its surface sank ");
  ASSERT_NE(sank, std::string::npos) << run.out;
  // 5 mm of target past the surface through the 400 N/m coupling: about 2 N, a dimple of millimetres.
  EXPECT_GT(std::stod(run.out.substr(sank + 17)), 1.0) << run.out;
  EXPECT_LT(std::stod(run.out.substr(sank + 17)), 5.0) << run.out;
}

TEST(SceneTool, ABadSceneOrBodyIsOneLineAndExitCodeTwo)
{
  const test::ToolRun missing = test::runTool(GOD_FINGER_SCENE_TOOL, "/nonexistent/scene.urdf");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(missing.err, "god_finger_scene: URDF '/nonexistent/scene.urdf': no such file or not readable\n");
  const test::ToolRun no_body = test::runTool(GOD_FINGER_SCENE_TOOL, kList + " --touch duck");
  EXPECT_EQ(no_body.exit_code, 2);
  EXPECT_NE(no_body.err.find("--touch 'duck': no such body"), std::string::npos) << no_body.err;
  const test::ToolRun no_file = test::runTool(GOD_FINGER_SCENE_TOOL, "");
  EXPECT_EQ(no_file.exit_code, 2);
  EXPECT_NE(no_file.err.find("usage: god_finger_scene FILE"), std::string::npos) << no_file.err;
}
}  // namespace
}  // namespace god_finger
