// A spawn or delete edits Bullet's world in place (scene_edit.h): the manifolds between the
// bodies it did not touch keep their points and warm starts, sleeping bodies stay asleep (and
// renumbered, still wake as they should), and what rested on a removed body falls. Real numbers:
// a loaded stack's trajectory after an edit far away is the trajectory without it, bit for bit.
#include "placed_block.h"
#include "scene_edit.h"
#include "world_build.h"
#include "world_core.h"

#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/scene_file.h"
#include "god_finger/scene/urdf_scene.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

namespace god_finger
{
namespace
{
const std::string kUrdf = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/";

// table_box (a 6 cm cube on the table) with a block resting on the cube: a stack; `more` appended.
SceneDescription stack(const std::vector<SceneDescription>& more = {})
{
  SceneDescription scene = loadUrdfScene(kUrdf + "scenes/table_box.urdf");
  scene.bodies.push_back(test::placedBlock("top", Eigen::Vector3d(0.0, 0.0, 0.075)).bodies[0]);
  for (const SceneDescription& object : more)
  {
    scene.bodies.insert(scene.bodies.end(), object.bodies.begin(), object.bodies.end());
  }
  return scene;
}

// Awake all the time (sleep off), the top block pushed sideways below its friction limit: the
// stack holds on its manifolds' friction and normal impulses, warm-started every step.
WorldParams awake()
{
  WorldParams params;
  params.sleep.time = 0.0;
  return params;
}

void loadedStep(GodFingerWorld* world, int top)
{
  world->applyBodyWrench(top, Eigen::Vector3d(0.15, 0.05, 0.0), Eigen::Vector3d(0.0, 0.0, 0.002));
  world->step();
}

struct Motion
{
  std::vector<Eigen::Matrix4d> poses;
  std::vector<Eigen::Vector3d> velocities;
};

// `steps` loaded steps of the stack (cube and top), recorded.
Motion record(GodFingerWorld* world, int steps)
{
  const int cube = world->scene().find("cube");
  const int top = world->scene().find("top");
  Motion motion;
  for (int i = 0; i < steps; ++i)
  {
    loadedStep(world, top);
    for (const int body : {cube, top})
    {
      const BodyState state = world->bodyState(body);
      motion.poses.push_back(state.pose.matrix());
      motion.velocities.push_back(state.linear_velocity);
      motion.velocities.push_back(state.angular_velocity);
    }
  }
  return motion;
}

// How many of the recorded values differ at all between two runs, and the largest difference.
struct Difference
{
  int differing = 0;
  double largest = 0.0;
};

Difference compare(const Motion& a, const Motion& b)
{
  Difference difference;
  for (std::size_t i = 0; i < a.poses.size(); ++i)
  {
    const double d = (a.poses[i] - b.poses[i]).cwiseAbs().maxCoeff();
    difference.differing += d != 0.0 ? 1 : 0;
    difference.largest = std::max(difference.largest, d);
  }
  for (std::size_t i = 0; i < a.velocities.size(); ++i)
  {
    const double d = (a.velocities[i] - b.velocities[i]).cwiseAbs().maxCoeff();
    difference.differing += d != 0.0 ? 1 : 0;
    difference.largest = std::max(difference.largest, d);
  }
  return difference;
}

constexpr int kSettle = 400;  // steps before the edit
constexpr int kAfter = 200;   // steps compared after it

TEST(SceneEditKeeps, ASpawnFarAwayLeavesALoadedStackBitForBit)
{
  GodFingerWorld edited(stack(), awake());
  GodFingerWorld plain(stack(), awake());
  record(&edited, kSettle);
  record(&plain, kSettle);
  // In the air far from the stack: it falls 0.2 m in the compared steps, touching nothing.
  EXPECT_TRUE(edited.addObject(test::placedBlock("far", Eigen::Vector3d(0.4, 0.4, 0.35))).empty());
  ASSERT_EQ(edited.bodyCount(), 4);
  const Difference difference = compare(record(&edited, kAfter), record(&plain, kAfter));
  std::printf("spawn far away: %d of %d stack values differ from the run without it, largest %.3e\n",
              difference.differing, kAfter * 2 * 3, difference.largest);
  EXPECT_EQ(difference.differing, 0);
  EXPECT_GT(edited.bodyState(3).linear_velocity.norm(), 1.0);  // the spawned block does fall
}

TEST(SceneEditKeeps, ADeleteFarAwayLeavesALoadedStackBitForBit)
{
  // The far block (body 0, before the stack: the stack's bodies are renumbered by the delete)
  // starts high enough to fall through both runs without touching anything.
  SceneDescription scene = loadUrdfScene(kUrdf + "scenes/table_box.urdf");
  scene.bodies.insert(scene.bodies.begin(), test::placedBlock("far", Eigen::Vector3d(0.4, 0.4, 4.0)).bodies[0]);
  scene.bodies.push_back(test::placedBlock("top", Eigen::Vector3d(0.0, 0.0, 0.075)).bodies[0]);
  GodFingerWorld edited(scene, awake());
  GodFingerWorld plain(scene, awake());
  record(&edited, kSettle);
  record(&plain, kSettle);
  const int cube = edited.scene().find("cube");
  EXPECT_EQ(edited.removeObject("far"), 1);
  ASSERT_EQ(edited.scene().find("cube"), cube - 1);
  const Difference difference = compare(record(&edited, kAfter), record(&plain, kAfter));
  std::printf("delete far away: %d of %d stack values differ from the run without it, largest %.3e\n",
              difference.differing, kAfter * 2 * 3, difference.largest);
  EXPECT_EQ(difference.differing, 0);
}

// The manifolds themselves: after an edit, the cube-table and top-cube manifolds are the same
// Bullet objects, with their points and applied impulses (the warm start of the next step).
struct ManifoldPoints
{
  const btPersistentManifold* manifold = nullptr;
  std::vector<double> impulses;  // N s: normal, then the two friction directions, per point
};

std::vector<ManifoldPoints> bodyManifolds(const internal::WorldCore& core)
{
  std::vector<ManifoldPoints> out;
  for (int m = 0; m < core.dispatcher->getNumManifolds(); ++m)
  {
    const btPersistentManifold* manifold = core.dispatcher->getManifoldByIndexInternal(m);
    if (manifold->getBody0()->getUserIndex() != manifold->getBody1()->getUserIndex() || manifold->getNumContacts() == 0)
    {
      continue;  // a proxy's, or an empty one
    }
    ManifoldPoints points{manifold, {}};
    for (int p = 0; p < manifold->getNumContacts(); ++p)
    {
      const btManifoldPoint& point = manifold->getContactPoint(p);
      points.impulses.push_back(point.m_appliedImpulse);
      points.impulses.push_back(point.m_appliedImpulseLateral1);
      points.impulses.push_back(point.m_appliedImpulseLateral2);
    }
    out.push_back(points);
  }
  return out;
}

TEST(SceneEditKeeps, AnEditKeepsTheUntouchedManifoldsAndTheirImpulses)
{
  internal::WorldCore core;
  core.params = awake();
  core.scene = stack();
  core.shared_scene = std::make_shared<const SceneDescription>(core.scene);
  internal::buildBodies(&core);
  internal::buildWorld(&core);
  GodFingerWorld unused(core.scene, core.params);  // the process-wide settings a world makes
  for (int i = 0; i < kSettle; ++i)
  {
    core.world->stepSimulation(core.params.time_step, 0);
  }
  const std::vector<ManifoldPoints> before = bodyManifolds(core);
  ASSERT_EQ(before.size(), 2u);  // cube-table, top-cube
  std::vector<int> old_of_new;
  SceneDescription next =
      internal::sceneWithObject(core, test::placedBlock("far", Eigen::Vector3d(0.4, 0.4, 0.35)), &old_of_new);
  internal::changeScene(&core, std::move(next), old_of_new, nullptr);
  next = internal::sceneWithout(core, "far", &old_of_new);
  internal::changeScene(&core, std::move(next), old_of_new, nullptr);
  const std::vector<ManifoldPoints> after = bodyManifolds(core);
  ASSERT_EQ(after.size(), before.size());
  for (std::size_t m = 0; m < before.size(); ++m)
  {
    EXPECT_EQ(after[m].manifold, before[m].manifold);
    ASSERT_EQ(after[m].impulses.size(), before[m].impulses.size());
    double normal = 0.0;
    for (std::size_t k = 0; k < before[m].impulses.size(); ++k)
    {
      EXPECT_EQ(after[m].impulses[k], before[m].impulses[k]);
      normal += k % 3 == 0 ? before[m].impulses[k] : 0.0;
    }
    std::printf("manifold %zu: %zu points, normal impulses summing to %.4e N s, kept\n", m,
                before[m].impulses.size() / 3, normal);
    EXPECT_GT(normal, 0.5 * 0.08 * 9.81 * core.params.time_step);  // at least the top block's weight
  }
}

// Default sleep: the scene comes to rest and sleeps; bodies at rest and asleep.
void settleAsleep(GodFingerWorld* world)
{
  for (int i = 0; i < 2000; ++i)
  {
    world->step();
  }
  for (int body = 0; body < world->bodyCount(); ++body)
  {
    if (!world->scene().bodies[body].is_static)
    {
      ASSERT_TRUE(world->bodyState(body).asleep) << world->scene().bodies[body].name;
    }
  }
}

TEST(SceneEditKeeps, SleepingBodiesStayAsleepAcrossASpawnAndADeleteElsewhere)
{
  // A block resting on the table beside the stack: body 3, renumbered to 2 when "top" goes.
  GodFingerWorld world(stack({test::placedBlock("side", Eigen::Vector3d(-0.3, 0.0, 0.015))}), WorldParams());
  settleAsleep(&world);
  const int side = world.scene().find("side");
  const Eigen::Isometry3d side_pose = world.bodyState(side).pose;
  EXPECT_TRUE(world.addObject(test::placedBlock("far", Eigen::Vector3d(0.4, 0.4, 0.2))).empty());
  for (const char* name : {"cube", "top", "side"})
  {
    EXPECT_TRUE(world.bodyState(world.scene().find(name)).asleep) << name << " after the spawn";
  }
  for (int i = 0; i < 50; ++i)
  {
    world.step();
    ASSERT_TRUE(world.bodyState(world.scene().find("cube")).asleep) << "step " << i;
    ASSERT_TRUE(world.bodyState(world.scene().find("side")).asleep) << "step " << i;
  }
  EXPECT_FALSE(world.bodyState(world.scene().find("far")).asleep);  // falling
  world.removeObject("far");
  world.removeObject("top");  // in front of "side": it is renumbered; the cube under "top" wakes
  EXPECT_TRUE(world.bodyState(world.scene().find("side")).asleep);
  for (int i = 0; i < 50; ++i)
  {
    world.step();
  }
  const int side_now = world.scene().find("side");
  EXPECT_EQ(side_now, side - 1);
  EXPECT_TRUE(world.bodyState(side_now).asleep);
  EXPECT_TRUE(world.bodyState(side_now).pose.isApprox(side_pose, 0.0));
  // Renumbered while asleep, it still wakes as itself: a push wakes it and moves it.
  for (int i = 0; i < 100; ++i)
  {
    world.applyBodyWrench(side_now, Eigen::Vector3d(2.0, 0.0, 0.0), Eigen::Vector3d::Zero());
    world.step();
  }
  const BodyState pushed = world.bodyState(side_now);
  std::printf("renumbered sleeper pushed: moved %.4f m\n",
              (pushed.pose.translation() - side_pose.translation()).norm());
  EXPECT_FALSE(pushed.asleep);
  EXPECT_GT(pushed.pose.translation().x() - side_pose.translation().x(), 0.01);
  EXPECT_TRUE(world.bodyState(world.scene().find("cube")).pose.translation().allFinite());
}

TEST(SceneEditKeeps, WhatSleptOnARemovedBodyWakesAndFalls)
{
  GodFingerWorld world(stack(), WorldParams());
  settleAsleep(&world);
  EXPECT_EQ(world.removeObject("cube"), 1);
  const int top = world.scene().find("top");
  EXPECT_FALSE(world.bodyState(top).asleep);
  for (int i = 0; i < 1000; ++i)
  {
    world.step();
  }
  const BodyState fallen = world.bodyState(top);
  std::printf("the top block, its cube removed: from z = 0.075 to %.5f m\n", fallen.pose.translation().z());
  EXPECT_NEAR(fallen.pose.translation().z(), 0.015, 0.001);  // on the table
}

TEST(SceneEditKeeps, RemovingTheTableDropsWhatSleptOnIt)
{
  GodFingerWorld world(stack(), WorldParams());
  settleAsleep(&world);
  world.removeObject("table");
  const int cube = world.scene().find("cube");
  for (int i = 0; i < 100; ++i)
  {
    world.step();
  }
  EXPECT_LT(world.bodyState(cube).pose.translation().z(), 0.03 - 0.03);  // fell at least 3 cm
}
}  // namespace
}  // namespace god_finger
