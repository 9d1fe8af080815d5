// A free soft body (<support value="resting">, physics/soft_body.h) in the world through a reset
// and a scene change: its Bullet body is kinematic and follows the volume's mean motion. Both
// rebuild Bullet's bodies. Before stop 43 a reset of a world with a free soft body crashed
// (the volume's reset moved the Bullet body the teardown had just deleted); and the ball's body
// was rebuilt static at the scene's pose and stayed so (makeSoftVolume returned before making it
// kinematic again): after an object was added elsewhere the ball's Bullet body, and with it its
// pose and the surface the fingers touch, jumped back to where the scene placed it (96.5 mm to
// 0) while its volume stayed pushed, and a reset's run went another way than the first.
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/scene_file.h"

#include <gtest/gtest.h>

#include <vector>

namespace god_finger
{
namespace
{
const std::string kUrdf = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/";

// A finger pushes the ball (radius 3 cm, resting at the origin) sideways at its equator for
// `steps` steps; returns its proxy's positions and the ball's positions, step by step.
std::vector<Eigen::Vector3d> push(GodFingerWorld* world, int ball, int finger, int steps)
{
  std::vector<Eigen::Vector3d> trace;
  world->setInterfaceTarget(finger, Eigen::Vector3d(0.0, 0.0, 0.03));
  for (int i = 0; i < steps; ++i)
  {
    world->step();
    trace.push_back(world->interfaceState(finger).proxy_position);
    trace.push_back(world->bodyState(ball).pose.translation());
  }
  return trace;
}

TEST(FreeSoftBodyWorld, AResetRepeatsTheFirstRunBitForBit)
{
  GodFingerWorld world(loadUrdfScene(kUrdf + "scenes/soft_ball.urdf"), WorldParams());
  const int ball = world.scene().find("soft_ball");
  ASSERT_GE(ball, 0);
  const int finger = world.addInterface(Eigen::Vector3d(-0.045, 0.0, 0.03));
  const std::vector<Eigen::Vector3d> first = push(&world, ball, finger, 800);
  EXPECT_GT(first.back().x(), 1e-3);  // pushed along +x
  world.reset();
  const std::vector<Eigen::Vector3d> again = push(&world, ball, finger, 800);
  EXPECT_EQ(first, again);
}

TEST(FreeSoftBodyWorld, AnObjectAddedElsewhereLeavesTheBallWhereItWas)
{
  GodFingerWorld world(loadUrdfScene(kUrdf + "scenes/soft_ball.urdf"), WorldParams());
  const int ball = world.scene().find("soft_ball");
  ASSERT_GE(ball, 0);
  const int finger = world.addInterface(Eigen::Vector3d(-0.045, 0.0, 0.03));
  push(&world, ball, finger, 800);
  world.setInterfaceTarget(finger, Eigen::Vector3d(-0.1, 0.0, 0.1));  // let go
  for (int i = 0; i < 1500; ++i)
  {
    world.step();
  }
  const BodyState before = world.bodyState(ball);
  ASSERT_GT(before.pose.translation().x(), 1e-3);
  ObjectPlacement placement;
  placement.name = "block";
  placement.pose.translation() = Eigen::Vector3d(0.25, 0.0, 0.02);
  EXPECT_TRUE(world.addObject(loadPlacedObject(kUrdf + "objects/block.urdf", placement)).empty());
  const BodyState after = world.bodyState(world.scene().find("soft_ball"));
  std::printf("the ball at x = %.3f mm before the object was added, %.3f mm after\n",
              1e3 * before.pose.translation().x(), 1e3 * after.pose.translation().x());
  EXPECT_TRUE(after.pose.isApprox(before.pose, 1e-12)) << after.pose.matrix() << "\n" << before.pose.matrix();
}

// Pushed off the table's edge the ball falls (its support ends where the table does); past the
// world's bounds it is put back where it started, settled, and counted (BodyState::left_world).
TEST(FreeSoftBodyWorld, PushedOffTheTableItFallsAndIsPutBack)
{
  GodFingerWorld world(loadUrdfScene(kUrdf + "scenes/soft_ball.urdf"), WorldParams());
  const int ball = world.scene().find("soft_ball");
  WorldSnapshot start;
  world.snapshot(&start);
  // Outside the table's 1 m square, a finger at the ball's equator, pushing it toward -x (its
  // edge at x = -0.5).
  const int finger = world.addInterface(Eigen::Vector3d(0.045, 0.0, 0.03));
  double lowest_centre = 0.0;
  int steps = 0;
  for (; steps < 8000 && world.bodyState(ball).left_world == 0; ++steps)
  {
    world.setInterfaceTarget(finger, Eigen::Vector3d(std::max(-0.75, 0.045 - 0.3 * steps * 1e-3), 0.0, 0.03));
    world.step();
    lowest_centre = std::min(lowest_centre, world.bodyState(ball).pose.translation().z());
  }
  const BodyState caught = world.bodyState(ball);
  std::printf("caught after %.3f s, having fallen to %.3f m\n", steps * 1e-3, lowest_centre);
  ASSERT_EQ(caught.left_world, 1);
  EXPECT_LT(lowest_centre, -0.5);  // it fell past the table's top (z = 0), toward the bounds
  // Put back at its start: the surface as the scene began.
  WorldSnapshot back;
  world.snapshot(&back);
  ASSERT_EQ(back.soft_surfaces.size(), 1u);
  EXPECT_EQ(back.soft_surfaces[0].vertices, start.soft_surfaces[0].vertices);
  EXPECT_NEAR(caught.pose.translation().x(), world.bodyState(ball).pose.translation().x(), 0.0);
  EXPECT_LT(std::abs(caught.pose.translation().x()), 1e-3);
}
}  // namespace
}  // namespace god_finger
