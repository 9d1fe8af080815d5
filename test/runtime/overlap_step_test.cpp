// The world's step stays real-time safe with the overlap push acting (src/physics/overlap_push.h):
// two god-fingers pressing side by side on one face, their areas overlapping and pushed apart,
// allocate nothing once warmed.
#include "allocation_counter.h"
#include "god_finger/physics/god_finger_world.h"

#include <gtest/gtest.h>

namespace god_finger
{
namespace
{
TEST(OverlapStep, PushingOverlappingFingersApartAllocatesNothing)
{
  BodyDescription slab;
  slab.name = "slab";
  slab.is_static = true;
  slab.geometry.kind = GeometryKind::kBox;
  slab.geometry.size = Eigen::Vector3d(0.5, 0.5, 0.1);
  slab.pose.translation() = Eigen::Vector3d(0, 0, -0.05);
  SceneDescription scene;
  scene.name = "slab";
  scene.bodies.push_back(slab);
  GodFingerWorld world(scene, WorldParams());
  for (const double x : {-0.005, 0.005})
  {
    const int i = world.addInterface(Eigen::Vector3d(x, 0.0, 0.01));
    world.setInterfaceTarget(i, Eigen::Vector3d(x, 0.0, -0.001));
  }
  for (int step = 0; step < 300; ++step)
  {
    world.step();
  }
  ASSERT_GT(world.interfaceState(0).overlap_area, 0.0);
  const long before = test::allocationCount();
  for (int step = 0; step < 300; ++step)
  {
    world.step();
  }
  const long during = test::allocationCount() - before;
  EXPECT_EQ(during, 0);
  // Still pushing at the end: the counted steps ran the push.
  EXPECT_GT(world.interfaceState(0).overlap_area, 0.0);
  EXPECT_GT(world.interfaceState(0).overlap_push.norm(), 0.0);
}
}  // namespace
}  // namespace god_finger
