// Sleeping (WorldParams::sleep): what rests out of the fingers' reach is not simulated, and wakes
// without a jump when a proxy or a woken body comes near. Each test states its scene; the table
// top is z = 0, boxes are 4 cm cubes of 50 g.
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace god_finger
{
namespace
{
constexpr double kBox = 0.04;  // m, edge
constexpr double kBoxMass = 0.05;

BodyDescription table()
{
  BodyDescription body;
  body.name = "table";
  body.is_static = true;
  body.geometry.kind = GeometryKind::kBox;
  body.geometry.size = Eigen::Vector3d(1.0, 1.0, 0.05);
  body.pose.translation() = Eigen::Vector3d(0.0, 0.0, -0.025);
  return body;
}

// A box whose bottom face is at `bottom` (m, world), centred on (x, y).
BodyDescription box(const std::string& name, double x, double y, double bottom)
{
  BodyDescription body;
  body.name = name;
  body.geometry.kind = GeometryKind::kBox;
  body.geometry.size = Eigen::Vector3d::Constant(kBox);
  body.mass = kBoxMass;
  body.inertia = Eigen::Matrix3d::Identity() * kBoxMass * 2.0 * kBox * kBox / 12.0;
  body.pose.translation() = Eigen::Vector3d(x, y, bottom + kBox / 2.0);
  return body;
}

void run(GodFingerWorld* world, double seconds)
{
  const long steps = std::lround(seconds / world->params().time_step);
  for (long i = 0; i < steps; ++i)
  {
    world->step();
  }
}

// The table, a stack of three boxes at the origin, one box at x = 0.2 and one box 5 cm in the air
// at x = -0.2.
SceneDescription stackScene()
{
  SceneDescription scene;
  scene.name = "stack";
  scene.bodies = {table(),
                  box("bottom", 0.0, 0.0, 0.0),
                  box("middle", 0.0, 0.0, kBox),
                  box("top", 0.0, 0.0, 2 * kBox),
                  box("alone", 0.2, 0.0, 0.0),
                  box("falling", -0.2, 0.0, 0.05)};
  return scene;
}

TEST(Sleeping, BodiesPlacedAtRestSleepFromTheStartAndAFallingOneFallsThenSleeps)
{
  GodFingerWorld world(stackScene(), WorldParams());
  const int falling = world.scene().find("falling");
  run(&world, 0.01);
  for (const char* name : {"bottom", "middle", "top", "alone"})
  {
    SCOPED_TRACE(name);
    EXPECT_TRUE(world.bodyState(world.scene().find(name)).asleep);
  }
  EXPECT_FALSE(world.bodyState(falling).asleep);
  EXPECT_EQ(world.counters().awake_bodies, 1);
  // It lands after sqrt(2 h / g) = 0.1 s, settles, and sleeps within the sleep time after that.
  run(&world, 0.1 + 0.2 + WorldParams().sleep.time);
  EXPECT_TRUE(world.bodyState(falling).asleep);
  EXPECT_NEAR(world.bodyState(falling).pose.translation().z(), kBox / 2.0, 1e-3);
  EXPECT_EQ(world.counters().awake_bodies, 0);
}

TEST(Sleeping, SleepTimeZeroKeepsEveryBodyAwake)
{
  WorldParams params;
  params.sleep.time = 0.0;
  GodFingerWorld world(stackScene(), params);
  run(&world, 1.0);
  EXPECT_EQ(world.counters().awake_bodies, 5);
}

TEST(Sleeping, AProxyApproachingASleepingStackWakesItWithoutAJump)
{
  GodFingerWorld world(stackScene(), WorldParams());
  const int top = world.scene().find("top");
  const Eigen::Vector3d top_face(0.0, 0.0, 3 * kBox);
  // The finger starts 10 cm above the stack and comes down at 5 cm/s, then presses 4 mm.
  const int finger = world.addInterface(top_face + Eigen::Vector3d(0.0, 0.0, 0.1));
  run(&world, 0.01);
  ASSERT_TRUE(world.bodyState(top).asleep);
  const Eigen::Isometry3d asleep_pose = world.bodyState(top).pose;
  const double dt = world.params().time_step;
  const CouplingProfile& coupling = world.coupling(finger);
  double largest_force_step = 0.0;
  Eigen::Vector3d previous_force = world.interfaceState(finger).user_force;
  long woke_at = -1;
  double jump_at_wake = 0.0;
  const long steps = std::lround(2.5 / dt);
  for (long i = 0; i < steps; ++i)
  {
    const double t = (i + 1) * dt;
    const double height = std::max(-0.004, 0.1 - 0.05 * t);
    world.setInterfaceTarget(finger, top_face + Eigen::Vector3d(0.0, 0.0, height));
    world.step();
    const Eigen::Vector3d force = world.interfaceState(finger).user_force;
    largest_force_step = std::max(largest_force_step, (force - previous_force).norm());
    previous_force = force;
    if (woke_at < 0 && !world.bodyState(top).asleep)
    {
      woke_at = i;
      jump_at_wake = (world.bodyState(top).pose.translation() - asleep_pose.translation()).norm();
    }
  }
  ASSERT_GE(woke_at, 0) << "the stack never woke";
  // It wakes before the finger touches it (the finger reaches the top face at 2 s), within
  // Bullet's 2 cm margin plus the proxy's radius and the box's margin.
  const double gap_at_wake = 0.1 - 0.05 * (woke_at + 1) * dt;
  EXPECT_GT(gap_at_wake, 0.0);
  EXPECT_LT(gap_at_wake, 0.03);
  // It moves no more in the step it wakes than a resting contact settles (about 1 um here; one
  // step of free fall would be g dt^2 = 9.8 um).
  EXPECT_LT(jump_at_wake, 5e-6) << "m moved in the step it woke";
  // The hand's force grows at the coupling's rate, at most stiffness x the target's motion per
  // step plus damping x its change of speed: no step from waking.
  EXPECT_LT(largest_force_step, coupling.stiffness * 0.05 * dt + coupling.damping * 0.05 + 0.05);
  // Pressed, the stack holds the finger: the hand feels about stiffness x press.
  EXPECT_GT(world.interfaceState(finger).user_force.z(), 0.5 * coupling.stiffness * 0.004);
  EXPECT_FALSE(world.bodyState(world.scene().find("bottom")).asleep);
  EXPECT_TRUE(world.bodyState(world.scene().find("alone")).asleep) << "a box 16 cm away woke";
}

TEST(Sleeping, AWokenNeighbourTopplesASleepingStack)
{
  // A box 1 cm beside the stack: a finger pushes it into the stack's bottom box at 10 cm/s.
  SceneDescription scene = stackScene();
  scene.bodies.push_back(box("pusher", -0.05, 0.0, 0.0));
  GodFingerWorld world(scene, WorldParams());
  const int top = world.scene().find("top");
  const Eigen::Vector3d behind(-0.05 - kBox / 2.0 - 0.004, 0.0, 0.02);
  const int finger = world.addInterface(behind - Eigen::Vector3d(0.02, 0.0, 0.0));
  run(&world, 0.01);
  ASSERT_TRUE(world.bodyState(top).asleep);
  ASSERT_TRUE(world.bodyState(world.scene().find("pusher")).asleep);
  const Eigen::Vector3d top_start = world.bodyState(top).pose.translation();
  const double dt = world.params().time_step;
  const long steps = std::lround(1.5 / dt);
  for (long i = 0; i < steps; ++i)
  {
    const double t = (i + 1) * dt;
    world.setInterfaceTarget(finger, behind + Eigen::Vector3d(std::min(0.1 * t, 0.1) - 0.02, 0.0, 0.0));
    world.step();
  }
  // The pusher moved 10 cm less its 1 cm gap into the stack: the stack's bottom was shoved and
  // the top box moved with it (or fell).
  EXPECT_GT((world.bodyState(top).pose.translation() - top_start).norm(), 0.02);
}

TEST(Sleeping, AWrenchOrAParameterChangeWakesABody)
{
  GodFingerWorld world(stackScene(), WorldParams());
  const int alone = world.scene().find("alone");
  run(&world, 0.01);
  ASSERT_TRUE(world.bodyState(alone).asleep);
  world.applyBodyWrench(alone, Eigen::Vector3d(0.0, 0.0, 2.0 * kBoxMass * 9.81), Eigen::Vector3d::Zero());
  world.step();
  EXPECT_FALSE(world.bodyState(alone).asleep);
  EXPECT_GT(world.bodyState(alone).linear_velocity.z(), 0.0) << "the wrench acted";
  run(&world, 1.5);
  ASSERT_TRUE(world.bodyState(alone).asleep);
  ContactParams contact = world.params().contact;
  contact.max_radius = 0.005;
  world.setContactParams(contact);
  EXPECT_EQ(world.counters().awake_bodies, 5);
  // Woken, they find their contacts anew (Bullet's manifolds went with them): a settling of
  // under 0.2 rad/s that decays within a few steps, then they sleep again.
  run(&world, world.params().sleep.time + 0.05);
  EXPECT_EQ(world.counters().awake_bodies, 0) << "at rest, they sleep again";
  world.setContactModel(ContactModel::kGodObject);
  EXPECT_EQ(world.counters().awake_bodies, 5);
}

TEST(Sleeping, AResetStartsAsleepAgainAndRepeatsTheFirstRun)
{
  GodFingerWorld world(stackScene(), WorldParams());
  run(&world, 0.5);
  const Eigen::Vector3d first = world.bodyState(world.scene().find("falling")).pose.translation();
  world.reset();
  run(&world, 0.5);
  EXPECT_EQ(world.bodyState(world.scene().find("falling")).pose.translation(), first);
  EXPECT_TRUE(world.bodyState(world.scene().find("top")).asleep);
}

TEST(Sleeping, AThousandRestingBoxesSleepAndAFingerWakesOnlyTheOneItPresses)
{
  // 1000 boxes 8 cm apart on a 3 m table (bench/scale_scene.h's scene, the scale section's).
  SceneDescription scene;
  scene.bodies.push_back(table());
  scene.bodies[0].geometry.size = Eigen::Vector3d(3.0, 3.0, 0.05);
  scene.bodies[0].pose.translation() = Eigen::Vector3d(1.2, 1.2, -0.025);
  for (int i = 0; i < 1000; ++i)
  {
    scene.bodies.push_back(box("box" + std::to_string(i), 0.08 * (i % 32), 0.08 * (i / 32), 0.0));
  }
  GodFingerWorld world(scene, WorldParams());
  const int finger = world.addInterface(Eigen::Vector3d(0.0, 0.0, kBox + 0.05));
  run(&world, 0.01);
  EXPECT_EQ(world.counters().awake_bodies, 0);
  // The finger comes down on box0 and presses it 4 mm: box0 wakes, its neighbours 4 cm away do not.
  const double dt = world.params().time_step;
  for (long i = 0; i < std::lround(0.5 / dt); ++i)
  {
    const double t = (i + 1) * dt;
    world.setInterfaceTarget(finger, Eigen::Vector3d(0.0, 0.0, kBox + 0.05 - 0.054 * std::min(1.0, t / 0.3)));
    world.step();
  }
  EXPECT_EQ(world.interfaceState(finger).contact_count, 1);
  EXPECT_EQ(world.counters().awake_bodies, 1);
  EXPECT_FALSE(world.bodyState(world.scene().find("box0")).asleep);
  EXPECT_TRUE(world.bodyState(world.scene().find("box1")).asleep);
}

TEST(Sleeping, BadSleepParametersAreRefusedByName)
{
  WorldParams params;
  params.sleep.time = -1.0;
  try
  {
    GodFingerWorld world(stackScene(), params);
    FAIL() << "accepted a negative sleep time";
  }
  catch (const InputError& error)
  {
    EXPECT_NE(std::string(error.what()).find("sleep_time"), std::string::npos) << error.what();
  }
  params.sleep.time = 0.5;
  params.sleep.speed = std::nan("");
  EXPECT_THROW(GodFingerWorld(stackScene(), params), InputError);
}
}  // namespace
}  // namespace god_finger
