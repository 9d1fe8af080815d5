// A free proxy carried across a late physics' skipped motion (GodFingerWorld::carryFreeProxy,
// the servo loop's catch-up): moved when its sphere's sweep meets nothing, left where it is when
// the sweep would cross a body (awake or asleep, out of Bullet's world) or while it touches one.
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/urdf_scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace god_finger
{
namespace
{
const std::string kScene = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes/table_sphere.urdf";

// The world after `steps` steps with the hand held at `hand` (the table's top is z = 0, the
// ball of 4 cm radius at the origin).
std::unique_ptr<GodFingerWorld> worldWithHandAt(const Eigen::Vector3d& hand, int steps)
{
  auto world = std::make_unique<GodFingerWorld>(loadUrdfScene(kScene), WorldParams());
  world->addInterface(hand);
  for (int k = 0; k < steps; ++k)
  {
    world->setInterfaceTarget(0, hand);
    world->step();
  }
  return world;
}

TEST(CarryFreeProxy, AFreeProxyIsCarriedWhereNothingIsInTheWay)
{
  const std::unique_ptr<GodFingerWorld> made = worldWithHandAt(Eigen::Vector3d(0.3, 0.0, 0.05), 5);
  GodFingerWorld& world = *made;
  const Eigen::Vector3d before = world.interfaceState(0).proxy_position;
  ASSERT_EQ(world.interfaceState(0).contact_count, 0);
  EXPECT_TRUE(world.carryFreeProxy(0, Eigen::Vector3d(0.004, 0.0, 0.0)));
  world.setInterfaceTarget(0, Eigen::Vector3d(0.304, 0.0, 0.05), Eigen::Vector3d::Zero());
  world.step();
  // Carried 4 mm: the coupling has (almost) nothing to pull across.
  EXPECT_NEAR((world.interfaceState(0).proxy_position - before).x(), 0.004, 1e-5);
  EXPECT_LT(world.interfaceState(0).user_force.norm(), 0.01);
  EXPECT_FALSE(world.carryFreeProxy(0, Eigen::Vector3d::Zero()));
  EXPECT_FALSE(world.carryFreeProxy(0, Eigen::Vector3d(std::nan(""), 0.0, 0.0)));
}

TEST(CarryFreeProxy, NotThroughABodyNorWhileTouchingOne)
{
  // 1 s: the ball (body 1) has settled and sleeps, out of Bullet's world.
  const std::unique_ptr<GodFingerWorld> made_above = worldWithHandAt(Eigen::Vector3d(0.3, 0.0, 0.05), 1000);
  GodFingerWorld& above = *made_above;
  ASSERT_TRUE(above.bodyState(1).asleep);
  const Eigen::Vector3d before = above.interfaceState(0).proxy_position;
  EXPECT_FALSE(above.carryFreeProxy(0, Eigen::Vector3d(0.0, 0.0, -0.1)));  // through the table's top
  EXPECT_FALSE(above.carryFreeProxy(0, Eigen::Vector3d(-0.3, 0.0, 0.0)));  // through the ball, asleep
  above.setInterfaceTarget(0, Eigen::Vector3d(0.3, 0.0, 0.05));
  above.step();
  EXPECT_NEAR((above.interfaceState(0).proxy_position - before).norm(), 0.0, 1e-9);

  const std::unique_ptr<GodFingerWorld> made_pressing = worldWithHandAt(Eigen::Vector3d(0.3, 0.0, 0.02), 5);
  GodFingerWorld& pressing = *made_pressing;
  for (int k = 0; k < 100; ++k)  // down to 5 mm under the top
  {
    pressing.setInterfaceTarget(0, Eigen::Vector3d(0.3, 0.0, 0.02 - 0.025 * std::min(1.0, k / 50.0)));
    pressing.step();
  }
  ASSERT_GT(pressing.interfaceState(0).contact_count, 0);
  EXPECT_FALSE(pressing.carryFreeProxy(0, Eigen::Vector3d(0.0, 0.0, 0.01)));  // held by the table
}
}  // namespace
}  // namespace god_finger
