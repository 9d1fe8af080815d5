// The overlap push in the world (src/physics/overlap_push.h, WorldParams::overlap): two fingers
// pressing side by side on one face overlap by the lens of their areas and are pushed apart, the
// push changing by at most force_rate * dt per step; apart, or with stiffness 0, they feel no push;
// a reset clears it; bad parameters are refused by name. The push never opens a grasp: two
// fingers side by side on one face of a free bar, pinched against a third on the opposite face,
// are not pushed even at the largest stiffness, and the bar stays held.
#include "god_finger/contact/area_overlap.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <cstdio>

#include <cmath>

namespace god_finger
{
namespace
{
// A static slab whose top face is the plane z = 0.
SceneDescription slabScene()
{
  BodyDescription slab;
  slab.name = "slab";
  slab.is_static = true;
  slab.geometry.kind = GeometryKind::kBox;
  slab.geometry.size = Eigen::Vector3d(0.5, 0.5, 0.1);
  slab.material.friction = 0.5;
  slab.pose.translation() = Eigen::Vector3d(0, 0, -0.05);
  SceneDescription scene;
  scene.name = "slab";
  scene.bodies.push_back(slab);
  return scene;
}

// Two fingers, `apart` (m) along x, start 1 cm above the slab and press 4 mm into it (hands at
// z = -0.001 under their proxies' rest at 0.003).
struct TwoFingers
{
  explicit TwoFingers(double apart, const WorldParams& params) : world(slabScene(), params)
  {
    for (const double x : {-0.5 * apart, 0.5 * apart})
    {
      const int i = world.addInterface(Eigen::Vector3d(x, 0.0, 0.01));
      world.setInterfaceTarget(i, Eigen::Vector3d(x, 0.0, -0.001));
    }
  }
  GodFingerWorld world;
};

TEST(OverlapPush, SideBySideFingersArePushedApartByTheirLens)
{
  WorldParams params;
  TwoFingers fingers(0.01, params);
  GodFingerWorld& world = fingers.world;
  double largest_change = 0.0;
  Eigen::Vector3d last = Eigen::Vector3d::Zero();
  bool overlapped = false;
  for (int step = 0; step < 300; ++step)
  {
    world.step();
    const InterfaceState& a = world.interfaceState(0);
    const InterfaceState& b = world.interfaceState(1);
    largest_change = std::max(largest_change, (a.overlap_push - last).norm());
    last = a.overlap_push;
    // Equal and opposite, along x (the line between the areas), a from b.
    EXPECT_NEAR((a.overlap_push + b.overlap_push).norm(), 0.0, 1e-12);
    EXPECT_LE(a.overlap_push.x(), 0.0);
    EXPECT_NEAR(a.overlap_push.y(), 0.0, 1e-12);
    EXPECT_NEAR(a.overlap_push.z(), 0.0, 1e-12);
    if (a.contact_count == 1 && b.contact_count == 1 && a.overlap_area > 0.0)
    {
      overlapped = true;
      const WorldContactArea& ca = a.contacts[0];
      const WorldContactArea& cb = b.contacts[0];
      // The lens of the two pads, centres where the proxies touch (same side of the face).
      const double d = Eigen::Vector2d(cb.point.x() - ca.point.x(), cb.point.y() - ca.point.y()).norm();
      EXPECT_NEAR(a.overlap_area, lensArea(ca.radius, cb.radius, d), 1e-12);
      EXPECT_EQ(a.overlap_area, b.overlap_area);
      EXPECT_EQ(ca.overlap_area, a.overlap_area);
    }
  }
  EXPECT_TRUE(overlapped);
  // The rate limit: 100 N/s at 1 ms, 0.1 N a step.
  EXPECT_LE(largest_change, params.overlap.force_rate * params.time_step + 1e-12);
  EXPECT_GT(largest_change, 0.5 * params.overlap.force_rate * params.time_step);
  // Pushed apart: the proxies moved out from under their hands (1 cm apart) along x.
  const double proxies_apart = world.interfaceState(1).proxy_position.x() - world.interfaceState(0).proxy_position.x();
  EXPECT_GT(proxies_apart, 0.012);
  // A reset clears the push: the first step feels none.
  world.reset();
  world.setInterfaceTarget(0, Eigen::Vector3d(-0.005, 0.0, -0.001));
  world.setInterfaceTarget(1, Eigen::Vector3d(0.005, 0.0, -0.001));
  world.step();
  EXPECT_EQ(world.interfaceState(0).overlap_push, Eigen::Vector3d::Zero());
}

// An object added or removed elsewhere while two fingers overlap (the spawn_object service): the
// push goes on from where it was, changing by no more than its rate allows in a step, instead of
// restarting from zero.
TEST(OverlapPush, ThePushGoesOnAcrossAnObjectAddedElsewhere)
{
  WorldParams params;
  TwoFingers fingers(0.01, params);
  GodFingerWorld& world = fingers.world;
  for (int step = 0; step < 300; ++step)
  {
    world.step();
  }
  const Eigen::Vector3d before = world.interfaceState(0).overlap_push;
  ASSERT_GT(before.norm(), 0.01);
  const SceneDescription far{
      "far", {boxBody("far", Eigen::Vector3d::Constant(0.02), 0.0, Eigen::Vector3d(0.2, 0.2, 0.01))}, {}, {}};
  EXPECT_TRUE(world.addObject(far).empty());
  world.step();
  const Eigen::Vector3d after = world.interfaceState(0).overlap_push;
  std::printf("overlap push across an edit: %.4f N before, %.4f N after one step\n", before.norm(), after.norm());
  EXPECT_LE((after - before).norm(), params.overlap.force_rate * params.time_step + 1e-12);
  world.removeObject("far");
  world.step();
  EXPECT_LE((world.interfaceState(0).overlap_push - after).norm(),
            params.overlap.force_rate * params.time_step + 1e-12);
}

TEST(OverlapPush, WithoutOverlapOrStiffnessThereIsNoPush)
{
  // 3 cm apart: two pads of at most 1 cm never meet.
  WorldParams params;
  TwoFingers apart(0.03, params);
  // Overlapping, but stiffness 0: the area is measured, nothing pushes.
  params.overlap.stiffness = 0.0;
  TwoFingers unpushed(0.01, params);
  double measured = 0.0;
  for (int step = 0; step < 300; ++step)
  {
    apart.world.step();
    unpushed.world.step();
    for (int i = 0; i < 2; ++i)
    {
      EXPECT_EQ(apart.world.interfaceState(i).overlap_area, 0.0);
      EXPECT_EQ(apart.world.interfaceState(i).overlap_push, Eigen::Vector3d::Zero());
      EXPECT_EQ(unpushed.world.interfaceState(i).overlap_push, Eigen::Vector3d::Zero());
    }
    measured = std::max(measured, unpushed.world.interfaceState(0).overlap_area);
  }
  EXPECT_GT(measured, 1e-4);
  // Unpushed, the proxies stay under their hands, 1 cm apart.
  EXPECT_NEAR(unpushed.world.interfaceState(1).proxy_position.x() - unpushed.world.interfaceState(0).proxy_position.x(),
              0.01, 1e-4);
}

// The other models' contacts are points: their areas' radii are only reported.
TEST(OverlapPush, OtherModelsHaveNoAreasToOverlap)
{
  WorldParams params;
  params.model = ContactModel::kGodObject;
  TwoFingers fingers(0.01, params);
  for (int step = 0; step < 300; ++step)
  {
    fingers.world.step();
    EXPECT_EQ(fingers.world.interfaceState(0).overlap_area, 0.0);
  }
  // Both touch, with areas of a radius that would overlap had they been god-fingers'.
  const InterfaceState& a = fingers.world.interfaceState(0);
  ASSERT_EQ(a.contact_count, 1);
  ASSERT_EQ(fingers.world.interfaceState(1).contact_count, 1);
  EXPECT_GT(a.contacts[0].radius, 0.005);
}

// A free 100 g bar, 8 mm thick (y), in mid-air: two fingers side by side on its -y face, 6 mm
// apart along x (their areas overlap), pinch it against a thumb on its +y face, each pulled 1 cm
// in; held 2 s. The largest stiffness the world takes (1e7 N/m^2) pushes neither side-by-side
// finger (each is pressed against by the thumb), and the bar neither slips nor turns.
TEST(OverlapPush, ThePushNeverOpensAGrasp)
{
  WorldParams params;
  params.overlap.stiffness = 1e7;
  const double thickness = 0.008;
  SceneDescription scene;
  scene.name = "bar";
  scene.bodies.push_back(boxBody("bar", Eigen::Vector3d(0.3, thickness, 0.04), 0.1, Eigen::Vector3d(0, 0, 0.2)));
  GodFingerWorld world(scene, params);
  const double face = 0.5 * thickness + params.coupling.proxy_radius;
  const Eigen::Vector3d starts[] = {{-0.003, -face, 0.2}, {0.003, -face, 0.2}, {0.0, face, 0.2}};
  const Eigen::Vector3d squeeze[] = {{0, 0.01, 0}, {0, 0.01, 0}, {0, -0.02, 0}};
  for (int i = 0; i < 3; ++i)
  {
    world.addInterface(starts[i]);
  }
  const Eigen::Vector3d start = world.bodyState(0).center_of_mass;
  double overlap = 0.0;
  double turn = 0.0;
  for (int step = 0; step < 2000; ++step)
  {
    for (int i = 0; i < 3; ++i)
    {
      world.setInterfaceTarget(i, starts[i] + squeeze[i]);
    }
    world.step();
    overlap = std::max(overlap, world.interfaceState(0).overlap_area);
    for (int i = 0; i < 3; ++i)
    {
      EXPECT_EQ(world.interfaceState(i).overlap_push, Eigen::Vector3d::Zero());
    }
    turn = std::max(turn, Eigen::AngleAxisd(world.bodyState(0).pose.linear()).angle());
  }
  EXPECT_GT(overlap, 1e-4);  // they do overlap, side by side on one face
  EXPECT_LT(turn, 0.01);
  // Held: the bar sank only by the couplings' sag (0.98 N over 3 x 400 N/m: 0.8 mm).
  EXPECT_LT((world.bodyState(0).center_of_mass - start).norm(), 0.002);
}

TEST(OverlapPush, BadParametersAreRefusedByName)
{
  WorldParams params;
  params.overlap.stiffness = -1.0;
  EXPECT_NE(validate(params).find("overlap_stiffness"), std::string::npos) << validate(params);
  params.overlap.stiffness = NAN;
  EXPECT_NE(validate(params).find("overlap_stiffness"), std::string::npos) << validate(params);
  params = WorldParams();
  params.overlap.force_rate = 0.0;
  EXPECT_NE(validate(params).find("overlap_force_rate"), std::string::npos) << validate(params);
  EXPECT_THROW(GodFingerWorld(slabScene(), params), InputError);
}
}  // namespace
}  // namespace god_finger
