// The world's bounds (WorldParams::world_margin): a body pushed off the table is caught once
// it has fallen world_margin below the scene, put back at its start at rest, counted with its
// time; the bodies that stay are untouched. Simulated time, deterministic.
#include "god_finger/support/input_error.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/urdf_scene.h"

#include <gtest/gtest.h>

#include <string>

namespace god_finger
{
namespace
{
const std::string kScenes = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes";

TEST(WorldBounds, ABallPushedOffTheTableIsPutBackAtItsStart)
{
  // table_sphere: a 1 m table (top z = 0, 4 cm thick), a 4 cm ball of 100 g at (0, 0, 0.04).
  const SceneDescription scene = loadUrdfScene(kScenes + "/table_sphere.urdf");
  GodFingerWorld world(scene, WorldParams());
  const int ball = scene.find("ball");
  const int table = scene.find("table");
  ASSERT_GE(ball, 0);
  const Eigen::Vector3d start = world.bodyState(ball).center_of_mass;
  // 1 N along +x for 0.1 s: about 0.7 m/s once rolling; it leaves the table's edge (x = 0.5 m).
  double lowest = start.z();
  double left_at = -1.0;
  for (int k = 0; k < 5000 && left_at < 0.0; ++k)
  {
    if (k < 100)
    {
      world.applyBodyWrench(ball, Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d::Zero());
    }
    world.step();
    const BodyState state = world.bodyState(ball);
    if (state.left_world > 0)
    {
      left_at = world.time();
      EXPECT_EQ(state.left_world, 1);
      EXPECT_DOUBLE_EQ(state.left_world_at, world.time());
      EXPECT_EQ(state.center_of_mass, start);  // put back where the scene put it
      EXPECT_EQ(state.pose.linear(), Eigen::Matrix3d::Identity());
      EXPECT_EQ(state.linear_velocity, Eigen::Vector3d::Zero());
      EXPECT_EQ(state.angular_velocity, Eigen::Vector3d::Zero());
    }
    else
    {
      lowest = std::min(lowest, state.center_of_mass.z());
    }
  }
  ASSERT_GT(left_at, 0.0) << "the ball was never caught; lowest z " << lowest << " m";
  // Caught within one step of crossing the bounds: the table's bottom (-0.04 m) less 1 m.
  EXPECT_LT(lowest, -1.04 + 0.05);
  EXPECT_GT(lowest, -1.04 - 0.05);
  EXPECT_GT(left_at, 0.5);
  EXPECT_LT(left_at, 3.0);
  // Back on the table it stays, and the table never moved.
  for (int k = 0; k < 1000; ++k)
  {
    world.step();
  }
  EXPECT_EQ(world.bodyState(ball).left_world, 1);
  EXPECT_NEAR((world.bodyState(ball).center_of_mass - start).norm(), 0.0, 1e-4);
  EXPECT_EQ(world.bodyState(table).left_world, 0);
  // A reset keeps the count (the nodes report each catch once).
  world.reset();
  EXPECT_EQ(world.bodyState(ball).left_world, 1);
}

TEST(WorldBounds, ABodyInsideTheBoundsIsNeverCaught)
{
  // The ball rolls 0.3 m on the table: never caught.
  const SceneDescription scene = loadUrdfScene(kScenes + "/table_sphere.urdf");
  WorldParams params;
  params.world_margin = 0.01;  // 1 cm: the table's edge is 0.51 m from the centre
  GodFingerWorld world(scene, params);
  const int ball = scene.find("ball");
  for (int k = 0; k < 2000; ++k)
  {
    if (k < 20)
    {
      world.applyBodyWrench(ball, Eigen::Vector3d(0.5, 0.0, 0.0), Eigen::Vector3d::Zero());
    }
    world.step();
    ASSERT_EQ(world.bodyState(ball).left_world, 0) << "t = " << world.time();
  }
  EXPECT_GT(world.bodyState(ball).center_of_mass.x(), 0.05);
}

TEST(WorldBounds, MarginMustBePositive)
{
  const SceneDescription scene = loadUrdfScene(kScenes + "/table_sphere.urdf");
  for (const double margin : {0.0, -1.0, std::nan("")})
  {
    WorldParams params;
    params.world_margin = margin;
    try
    {
      GodFingerWorld world(scene, params);
      FAIL() << "world_margin " << margin << " accepted";
    }
    catch (const InputError& error)
    {
      EXPECT_NE(std::string(error.what()).find("world_margin"), std::string::npos) << error.what();
    }
  }
}
}  // namespace
}  // namespace god_finger
