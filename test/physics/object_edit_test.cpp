// Objects added and removed while the world runs (GodFingerWorld::addObject / removeObject, the
// spawn_object and delete_object services): an object file placed at a pose joins the scene,
// falls and rests, and can be pressed; every other body keeps its pose and motion across the
// change exactly; a finger pressing an object that is removed lets go over let_go_time (its
// force falls in steps of F / (let_go_time / dt), not at once); bad edits change nothing.
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/scene_file.h"
#include "god_finger/scene/urdf_scene.h"
#include "placed_block.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <thread>

namespace god_finger
{
namespace
{
const std::string kUrdf = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/";

void expectSameMotion(const BodyState& before, const BodyState& after)
{
  EXPECT_TRUE(before.pose.isApprox(after.pose, 1e-12)) << before.pose.matrix() << "\n" << after.pose.matrix();
  EXPECT_TRUE(before.linear_velocity.isApprox(after.linear_velocity, 1e-12));
  EXPECT_TRUE((before.angular_velocity - after.angular_velocity).norm() < 1e-12);
}

TEST(ObjectEdit, AnAddedObjectFallsRestsAndTheOthersKeepTheirMotion)
{
  GodFingerWorld world(loadUrdfScene(kUrdf + "scenes/table_box.urdf"), WorldParams());
  const int cube = world.scene().find("cube");
  ASSERT_GE(cube, 0);
  for (int i = 0; i < 20; ++i)  // pushed: sliding
  {
    world.applyBodyWrench(cube, Eigen::Vector3d(20.0, 0.0, 0.0), Eigen::Vector3d::Zero());
    world.step();
  }
  const BodyState sliding = world.bodyState(cube);
  ASSERT_GT(sliding.linear_velocity.x(), 0.01);
  const double time = world.time();
  const std::vector<std::string> warnings =
      world.addObject(test::placedBlock("block", Eigen::Vector3d(0.2, 0.0, 0.05)));
  EXPECT_TRUE(warnings.empty());
  ASSERT_EQ(world.bodyCount(), 3);
  EXPECT_EQ(world.scene().bodies[2].name, "block");
  EXPECT_EQ(world.time(), time);  // the clock goes on
  expectSameMotion(sliding, world.bodyState(cube));
  WorldSnapshot snapshot;
  world.snapshot(&snapshot);
  ASSERT_TRUE(snapshot.scene != nullptr);
  EXPECT_EQ(snapshot.scene->bodies.size(), 3u);
  EXPECT_EQ(snapshot.scene->bodies[2].name, "block");
  for (int i = 0; i < 1500; ++i)
  {
    world.step();
  }
  const BodyState rested = world.bodyState(2);
  std::printf("added block: rests at z = %.5f m (its half height 0.015 m), speed %.2e m/s\n",
              rested.pose.translation().z(), rested.linear_velocity.norm());
  EXPECT_NEAR(rested.pose.translation().z(), 0.015, 0.001);
  EXPECT_NEAR(rested.pose.translation().x(), 0.2, 0.001);
  EXPECT_LT(rested.linear_velocity.norm(), 1e-3);
  // A reset puts it back where it was added.
  world.reset();
  EXPECT_NEAR(world.bodyState(2).pose.translation().z(), 0.05, 1e-12);
}

// A finger pressing the added block 4 mm deep; the block is removed. Returns the largest change
// of the force on the hand from one step to the next after the removal, and the force 0.3 s later.
struct LetGo
{
  double pressed = 0.0;       // N, before the removal
  double largest_step = 0.0;  // N
  double after = 0.0;         // N
};

LetGo pressAndRemove(double let_go_time)
{
  WorldParams params;
  params.let_go_time = let_go_time;
  GodFingerWorld world(loadUrdfScene(kUrdf + "scenes/table_box.urdf"), params);
  EXPECT_TRUE(world.addObject(test::placedBlock("block", Eigen::Vector3d(0.2, 0.0, 0.015))).empty());
  const double radius = params.coupling.proxy_radius;
  const int finger = world.addInterface(Eigen::Vector3d(0.2, 0.0, 0.06));
  // The hand 25 mm above the table: through the block's top (3 cm), not into the table.
  const Eigen::Vector3d pressing(0.2, 0.0, 0.025 + radius);
  for (int i = 1; i <= 1000; ++i)
  {
    world.setInterfaceTarget(finger, Eigen::Vector3d(0.2, 0.0, 0.06) +
                                         (pressing - Eigen::Vector3d(0.2, 0.0, 0.06)) * std::min(1.0, i / 500.0));
    world.step();
  }
  LetGo result;
  result.pressed = world.interfaceState(finger).user_force.norm();
  EXPECT_EQ(world.interfaceState(finger).contact_count, 1);
  EXPECT_EQ(world.removeObject("block"), 1);
  EXPECT_EQ(world.bodyCount(), 2);
  Eigen::Vector3d previous = world.interfaceState(finger).user_force;
  for (int i = 0; i < 300; ++i)
  {
    world.setInterfaceTarget(finger, pressing);
    world.step();
    const Eigen::Vector3d force = world.interfaceState(finger).user_force;
    result.largest_step = std::max(result.largest_step, (force - previous).norm());
    previous = force;
  }
  result.after = previous.norm();
  return result;
}

TEST(ObjectEdit, AFingerPressingARemovedObjectLetsGoOverLetGoTime)
{
  const LetGo smooth = pressAndRemove(0.1);
  const LetGo at_once = pressAndRemove(0.0);
  std::printf(
      "pressing %.3f N; removed: largest force step %.4f N over let_go_time 0.1 s, %.4f N at once; "
      "0.3 s later %.2e N\n",
      smooth.pressed, smooth.largest_step, at_once.largest_step, smooth.after);
  ASSERT_GT(smooth.pressed, 1.0);
  // A linear ramp over 100 steps: about F / 100 a step (the proxy's lag adds little).
  EXPECT_LT(smooth.largest_step, 2.0 * smooth.pressed / 100.0);
  // What the ramp avoids: the free proxy springs to the hand in a few steps.
  EXPECT_GT(at_once.largest_step, 5.0 * smooth.largest_step);
  EXPECT_LT(smooth.after, 1e-3);  // let go: free space
}

// Two edits between two steps (two service calls, queued commands): the second sees no contact
// numbered in the scene before the first (the finger pressed the last body, which is gone).
TEST(ObjectEdit, EditsBetweenTwoStepsSeeNoStaleContacts)
{
  GodFingerWorld world(loadUrdfScene(kUrdf + "scenes/table_box.urdf"), WorldParams());
  EXPECT_TRUE(world.addObject(test::placedBlock("block", Eigen::Vector3d(0.2, 0.0, 0.015))).empty());
  const double radius = world.params().coupling.proxy_radius;
  const int finger = world.addInterface(Eigen::Vector3d(0.2, 0.0, 0.05));
  world.setInterfaceTarget(finger, Eigen::Vector3d(0.2, 0.0, 0.026 + radius));
  for (int i = 0; i < 500; ++i)
  {
    world.step();
  }
  ASSERT_EQ(world.interfaceState(finger).contact_count, 1);
  ASSERT_EQ(world.interfaceState(finger).contacts[0].body, 2);
  world.removeObject("block");
  WorldSnapshot snapshot;
  world.snapshot(&snapshot);
  EXPECT_EQ(snapshot.interfaces[0].contact_count, 0);  // none numbered in the old scene
  EXPECT_EQ(snapshot.scene->bodies.size(), 2u);
  world.removeObject("cube");
  EXPECT_TRUE(world.addObject(test::placedBlock("block", Eigen::Vector3d(-0.2, 0.0, 0.015))).empty());
  for (int i = 0; i < 200; ++i)
  {
    world.step();
  }
  EXPECT_EQ(world.bodyCount(), 2);
  EXPECT_EQ(world.interfaceState(finger).contact_count, 0);  // let go: over the table, in the air
}

// The costly part of an add (the shapes, trees and hulls) in another thread, as the services do;
// a prepared object is added once.
TEST(ObjectEdit, AnObjectPreparedInAnotherThreadIsAddedOnce)
{
  GodFingerWorld world(loadUrdfScene(kUrdf + "scenes/table_box.urdf"), WorldParams());
  std::unique_ptr<PreparedObject> prepared;
  std::thread service(
      [&prepared, &world]
      {
        prepared =
            GodFingerWorld::prepareObject(test::placedBlock("block", Eigen::Vector3d(0.2, 0, 0.05)), world.params());
      });
  service.join();
  ASSERT_TRUE(prepared != nullptr);
  EXPECT_EQ(prepared->object().bodies.size(), 1u);
  EXPECT_TRUE(world.addObject(prepared.get()).empty());
  EXPECT_EQ(world.bodyCount(), 3);
  EXPECT_THROW(world.addObject(prepared.get()), InputError);
  EXPECT_EQ(world.bodyCount(), 3);
  EXPECT_THROW(GodFingerWorld::prepareObject(SceneDescription(), WorldParams()), InputError);
}

TEST(ObjectEdit, BadEditsChangeNothing)
{
  GodFingerWorld world(loadUrdfScene(kUrdf + "scenes/table_box.urdf"), WorldParams());
  EXPECT_THROW(world.addObject(test::placedBlock("cube", Eigen::Vector3d(0.2, 0, 0.05))), InputError);  // a name taken
  EXPECT_THROW(world.removeObject("nothing"), InputError);
  EXPECT_THROW(world.removeObject(""), InputError);
  EXPECT_THROW(world.addObject(SceneDescription()), InputError);
  EXPECT_EQ(world.bodyCount(), 2);
  try
  {
    EXPECT_TRUE(world.addObject(test::placedBlock("cube", Eigen::Vector3d(0.2, 0, 0.05))).empty());
  }
  catch (const InputError& error)
  {
    EXPECT_NE(std::string(error.what()).find("'cube' already"), std::string::npos) << error.what();
  }
  ObjectPlacement nan;
  nan.pose.translation().x() = std::nan("");
  EXPECT_THROW(loadPlacedObject(kUrdf + "objects/block.urdf", nan), InputError);
  EXPECT_THROW(loadPlacedObject(kUrdf + "lists/table_objects.yaml", ObjectPlacement()), InputError);
  EXPECT_THROW(loadPlacedObject(kUrdf + "objects/none.urdf", ObjectPlacement()), InputError);
}

TEST(ObjectEdit, AnObjectStartingInsideAnotherIsWarnedAbout)
{
  GodFingerWorld world(loadUrdfScene(kUrdf + "scenes/table_box.urdf"), WorldParams());
  const std::vector<std::string> warnings =
      world.addObject(test::placedBlock("block", Eigen::Vector3d(0.0, 0.0, 0.03)));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("'block'"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("'cube'"), std::string::npos) << warnings[0];
}

TEST(ObjectEdit, AnObjectAddedOverAFingerIsWarnedAbout)
{
  GodFingerWorld world(loadUrdfScene(kUrdf + "scenes/table_box.urdf"), WorldParams());
  world.addInterface(Eigen::Vector3d(0.2, 0.0, 0.015));
  const std::vector<std::string> warnings =
      world.addObject(test::placedBlock("block", Eigen::Vector3d(0.2, 0.0, 0.015)));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("finger 0 starts"), std::string::npos) << warnings[0];
}

TEST(ObjectEdit, RemovingAJointedBodyRemovesItsJoint)
{
  GodFingerWorld world(loadUrdfScene(kUrdf + "scenes/door.urdf"), WorldParams());
  ASSERT_EQ(world.jointCount(), 1);
  const int before = world.bodyCount();
  EXPECT_EQ(world.removeObject("door"), 1);
  EXPECT_EQ(world.bodyCount(), before - 1);
  EXPECT_EQ(world.jointCount(), 0);
  for (int i = 0; i < 100; ++i)
  {
    world.step();
  }
  // An articulated object added at run time: its joint with it, relative to the world.
  ObjectPlacement placement;
  placement.name = "second";
  placement.pose.translation() = Eigen::Vector3d(0.0, 0.5, 0.0);
  const SceneDescription door = loadPlacedObject(kUrdf + "scenes/door.urdf", placement);
  EXPECT_TRUE(world.addObject(door).empty());
  EXPECT_EQ(world.jointCount(), 1);
  for (int i = 0; i < 500; ++i)
  {
    world.step();
  }
  EXPECT_NEAR(world.jointState(0).position, 0.0, 1e-3);  // the hinge holds it where it was placed
}
}  // namespace
}  // namespace god_finger
