// Hands in the servo loop, without ROS, on simulated time: a pose source's fingers are run as
// one interface each in one tick; a finger whose pose stream is lost (non-finite poses, fewer
// poses, stale stamps) lets go after pose_timeout, its samples say so, and the others go on
// pressing; the fake hand grasps and lifts the mug.
#include "god_finger/devices/fake_hand.h"
#include "god_finger/devices/hand_device.h"
#include "god_finger/devices/pose_source.h"
#include "god_finger/haptics/force_guard.h"
#include "god_finger/runtime/servo_loop.h"
#include "god_finger/scene/urdf_scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace god_finger
{
namespace
{
const std::string kTable = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes/table_sphere.urdf";
const std::string kMug = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes/table_mug.urdf";
constexpr double kTimeout = 0.05;  // s

// Three fingertips pressing the table top (z = 0) 5 mm deep, far from the ball.
const Eigen::Vector3d kPressed[3] = {{0.15, 0.1, -0.005}, {0.2, 0.1, -0.005}, {0.25, 0.1, -0.005}};

std::vector<ServoInterface> fingersOf(std::unique_ptr<HapticDevice> hand)
{
  std::vector<ServoInterface> interfaces;
  for (DeviceFinger& finger : hand->fingers())
  {
    ServoInterface interface;
    interface.name = "hand/" + finger.name;
    interface.device = std::move(finger.device);
    interfaces.push_back(std::move(interface));
  }
  return interfaces;
}

std::unique_ptr<ServoLoop> makeLoop(const std::string& scene, std::vector<ServoInterface> interfaces)
{
  ServoLoopParams params;
  params.simulated_time = true;
  params.real_time_factor = 0.0;
  auto loop = std::make_unique<ServoLoop>(std::make_unique<GodFingerWorld>(loadUrdfScene(scene), WorldParams()),
                                          std::move(interfaces), params);
  loop->prepare();
  return loop;
}

struct PoseHand
{
  double now = 0.0;  // s: the pose source's clock, the loop's time here
  std::shared_ptr<PoseFeed> feed;
  std::unique_ptr<ServoLoop> loop;
  std::vector<ServoSample> last;  // per interface, the newest sample
  int kept_interface = -1;        // >= 0: every sample of that interface goes to `kept` too
  std::vector<ServoSample> kept;

  PoseHand()
  {
    PoseSourceParams params;
    params.fingers = {"thumb", "index", "middle"};
    params.pose_timeout = kTimeout;
    feed = std::make_shared<PoseFeed>(3);
    auto source = makePoseSource(params, feed, [this]() { return now; });
    loop = makeLoop(kTable, fingersOf(makeHandDevice(source)));
    last.resize(3);
  }
  // Runs ticks until `until` (s), the tracker writing write(t) before each.
  template <class Write>
  void runUntil(double until, Write write)
  {
    const double dt = loop->period();
    while (now + 0.5 * dt < until)
    {
      now += dt;
      write(now);
      loop->tick(now);
      ServoSample sample;
      while (loop->samples().tryPop(&sample))
      {
        last[sample.interface] = sample;
        if (sample.interface == kept_interface)
        {
          kept.push_back(sample);
        }
      }
    }
  }
  void writeAll(double t, int fingers, int nan_finger = -1, double age = 0.0)
  {
    std::vector<FingerPose> poses(fingers);
    for (int i = 0; i < fingers; ++i)
    {
      poses[i].position = i == nan_finger ? Eigen::Vector3d::Constant(NAN) : kPressed[i];
      poses[i].stamp = t - age;
    }
    feed->write(poses);
  }
};

TEST(HandLoop, RunsEveryFingerOfAHandAsItsOwnInterface)
{
  PoseHand hand;
  ASSERT_EQ(hand.loop->interfaces().size(), 3u);
  EXPECT_EQ(hand.loop->interfaces()[2].name, "hand/middle");
  // No pose yet: every finger untracked, at the source's rest, pressing nothing.
  hand.runUntil(0.01, [](double) {});
  for (const ServoSample& sample : hand.last)
  {
    EXPECT_FALSE(sample.tracked);
    EXPECT_LT(sample.user_force.norm(), 1e-9);
  }
  // Tracked from 0.01 s: the targets ramp from the proxies to the poses over the soft start.
  hand.runUntil(0.11 + ForceGuardParams().soft_start, [&hand](double t) { hand.writeAll(t, 3); });
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_TRUE(hand.last[i].tracked) << i;
    EXPECT_NEAR(hand.last[i].interface_position.x(), kPressed[i].x(), 1e-12) << i;
    // 5 mm into the table at the default coupling's stiffness: the hand is pushed up.
    EXPECT_GT(hand.last[i].user_force.z(), 1.0) << i;
  }
}

// The tracker loses one finger: non-finite poses (the same for fewer poses in the array).
void expectOnlyMiddleLetsGo(bool fewer_poses)
{
  PoseHand hand;
  hand.runUntil(0.5, [&hand](double t) { hand.writeAll(t, 3); });
  ASSERT_GT(hand.last[2].user_force.z(), 1.0);
  const double lost_at = hand.now;
  auto lose = [&hand, fewer_poses](double t) { fewer_poses ? hand.writeAll(t, 2) : hand.writeAll(t, 3, 2); };
  // Within its timeout the finger still presses (a late pose is not yet a lost one).
  hand.runUntil(lost_at + 0.8 * kTimeout, lose);
  EXPECT_TRUE(hand.last[2].tracked);
  EXPECT_GT(hand.last[2].user_force.z(), 1.0);
  hand.runUntil(lost_at + 0.3, lose);
  EXPECT_FALSE(hand.last[2].tracked);
  // Named for why: missing from the array, or its poses stopped (here: non-finite ones).
  EXPECT_EQ(hand.last[2].missing, fewer_poses);
  EXPECT_LT(hand.last[2].user_force.norm(), 0.01);  // let go: no coupling force
  EXPECT_GT(hand.loop->counters().untracked_readings.load(), 0);
  for (int i = 0; i < 2; ++i)  // the others go on
  {
    EXPECT_TRUE(hand.last[i].tracked) << i;
    EXPECT_GT(hand.last[i].user_force.z(), 1.0) << i;
  }
  // Seen again: it presses again (its target ramped back in over the soft start).
  hand.runUntil(lost_at + 0.4 + ForceGuardParams().soft_start, [&hand](double t) { hand.writeAll(t, 3); });
  EXPECT_TRUE(hand.last[2].tracked);
  EXPECT_FALSE(hand.last[2].missing);
  EXPECT_GT(hand.last[2].user_force.z(), 1.0);
}

TEST(HandLoop, AFingerWhosePosesTurnNonFiniteLetsGoTheOthersGoOn)
{
  expectOnlyMiddleLetsGo(false);
}

TEST(HandLoop, AFingerMissingFromTheArrayLetsGoTheOthersGoOn)
{
  expectOnlyMiddleLetsGo(true);
}

// Tracked again 2 cm from where it let go (the hand moved while the tracker lost it), the
// finger's target ramps from its proxy to the pose over the force guard's soft start: the
// proxy's coupling force rises without a step (a jump of the target would step it by the
// spring's 400 N/m x 2 cm plus the jump's damping, saturated at 20 N), and ends where the
// pose says, pressing as before.
TEST(HandLoop, AFingerTrackedAgainRampsBackWithoutAForceStep)
{
  PoseHand hand;
  hand.runUntil(0.5, [&hand](double t) { hand.writeAll(t, 3); });
  hand.runUntil(0.8, [&hand](double t) { hand.writeAll(t, 3, 2); });
  ASSERT_FALSE(hand.last[2].tracked);
  ASSERT_LT(hand.last[2].user_force.norm(), 0.01);
  // Let go, the proxy rests where it was released, on the table top (the target's jump onto it
  // kicks nothing; it flew off at about 1 m/s when the jump entered the coupling's damping):
  // 0.25 s later within 1 mm of the pose it pressed from along the table, its centre less than
  // 5 mm above the top.
  const Eigen::Vector3d released = hand.last[2].proxy_position;
  EXPECT_LT((released.head<2>() - kPressed[2].head<2>()).norm(), 0.001) << released.transpose();
  EXPECT_GT(released.z(), 0.0);
  EXPECT_LT(released.z(), 0.005);
  const Eigen::Vector3d moved = kPressed[2] + Eigen::Vector3d(0.02, 0.0, 0.0);
  auto write = [&hand, &moved](double t)
  {
    std::vector<FingerPose> poses(3);
    for (int i = 0; i < 3; ++i)
    {
      poses[i].position = i == 2 ? moved : kPressed[i];
      poses[i].stamp = t;
    }
    hand.feed->write(poses);
  };
  const double soft_start = ForceGuardParams().soft_start;
  ASSERT_GT(soft_start, 0.0);
  hand.kept_interface = 2;
  hand.runUntil(0.8 + soft_start + 0.2, write);
  double largest_step = 0.0;  // N: between successive ticks
  Eigen::Vector3d previous = Eigen::Vector3d::Zero();
  for (const ServoSample& sample : hand.kept)
  {
    ASSERT_TRUE(sample.tracked);
    largest_step = std::max(largest_step, (sample.user_force - previous).norm());
    previous = sample.user_force;
  }
  std::printf("re-acquired finger: largest force step %.4f N per tick over %zu ticks, final |F| %.3f N\n", largest_step,
              hand.kept.size(), hand.last[2].user_force.norm());
  EXPECT_LT(largest_step, 0.25);
  EXPECT_NEAR((hand.last[2].interface_position - moved).norm(), 0.0, 1e-12);  // the ramp ended at the pose
  EXPECT_GT(hand.last[2].user_force.z(), 1.0);                                // pressing again
}

TEST(HandLoop, StaleStampsLetEveryFingerGo)
{
  PoseHand hand;
  hand.runUntil(0.5, [&hand](double t) { hand.writeAll(t, 3); });
  // The stream goes on, but its stamps are 2 timeouts old: late poses.
  hand.runUntil(0.8, [&hand](double t) { hand.writeAll(t, 3, -1, 2.0 * kTimeout); });
  for (const ServoSample& sample : hand.last)
  {
    EXPECT_FALSE(sample.tracked);
    EXPECT_LT(sample.user_force.norm(), 0.01);
  }
}

// The mug's height (m, its origin) at 4 s: closed, lifted by 10 cm at 3.5 s, held.
double mugHeightAfterLift(int fingers, bool oriented = true)
{
  FakeHandParams params;
  params.fingers = fingers;
  params.oriented = oriented;
  auto source = makeFakeHand(params);
  source->setScriptStart(0.0);
  auto loop = makeLoop(kMug, fingersOf(makeHandDevice(source)));
  EXPECT_EQ(loop->interfaces().size(), static_cast<std::size_t>(fingers + 1));
  bool checked_orientation = false;
  double mug_z = 0.0;
  WorldSnapshot snapshot;
  ServoSample sample;
  for (long k = 1; k <= 4000; ++k)  // 4 s: closed, lifted by 10 cm at 3.5 s, held
  {
    loop->tick(k * loop->period());
    while (loop->samples().tryPop(&sample))
    {
    }
    if (k == 1000 && !checked_orientation)
    {
      // Closed on the mug: every finger oriented (or none), its proxy at the hand's orientation.
      checked_orientation = true;
      const std::vector<Eigen::Quaterniond> held = fakeHandOrientations(params);
      for (int i = 0; i <= fingers; ++i)
      {
        const InterfaceState& state = loop->world().interfaceState(i);
        EXPECT_EQ(state.oriented, oriented);
        if (oriented)
        {
          EXPECT_LT(state.proxy_orientation.angularDistance(held[i]), 1e-3);
        }
      }
    }
    while (loop->snapshots().tryPop(&snapshot))
    {
      mug_z = -1.0;  // the highest body: the mug (the table's is at -0.02)
      for (const BodyState& body : snapshot.bodies)
      {
        mug_z = std::max(mug_z, body.pose.translation().z());
      }
    }
  }
  return mug_z;
}

// A pose source's orientations (PoseArray, TF; setPoseOrientation): a finger given one is an
// oriented finger at that orientation; an all-zero quaternion (unset) leaves it 3-DOF; a NaN one
// is ignored and counted by the loop, never reaching the physics.
TEST(HandLoop, PoseOrientationsOrientTheirFingersUnsetOnesStay3Dof)
{
  PoseHand hand;
  const Eigen::Quaterniond rolled(Eigen::AngleAxisd(M_PI + 0.3, Eigen::Vector3d::UnitX()));
  hand.runUntil(0.2,
                [&hand, &rolled](double t)
                {
                  std::vector<FingerPose> poses(3);
                  for (int i = 0; i < 3; ++i)
                  {
                    poses[i].position = kPressed[i] + Eigen::Vector3d(0.0, 0.0, 0.02);  // above the table
                    poses[i].stamp = t;
                  }
                  setPoseOrientation(0.0, 0.0, 0.0, 0.0, &poses[0]);  // unset
                  setPoseOrientation(rolled.x(), rolled.y(), rolled.z(), rolled.w(), &poses[1]);
                  setPoseOrientation(NAN, 0.0, 0.0, 1.0, &poses[2]);
                  hand.feed->write(poses);
                });
  const GodFingerWorld& world = hand.loop->world();
  EXPECT_FALSE(world.interfaceState(0).oriented);
  ASSERT_TRUE(world.interfaceState(1).oriented);
  EXPECT_LT(world.interfaceState(1).interface_orientation.angularDistance(rolled), 1e-12);
  EXPECT_LT(world.interfaceState(1).proxy_orientation.angularDistance(rolled), 1e-6);  // at rest there
  EXPECT_FALSE(world.interfaceState(2).oriented);
  EXPECT_EQ(hand.loop->counters().rejected_orientations.load(), 200);  // the NaN one, every tick
  EXPECT_EQ(world.counters().rejected_targets, 0);
}

// The mug's pose (the highest body's) after `ticks` of the fake hand's script.
Eigen::Isometry3d mugPoseAfter(const FakeHandParams& params, long ticks)
{
  auto source = makeFakeHand(params);
  source->setScriptStart(0.0);
  auto loop = makeLoop(kMug, fingersOf(makeHandDevice(source)));
  Eigen::Isometry3d mug = Eigen::Isometry3d::Identity();
  WorldSnapshot snapshot;
  ServoSample sample;
  for (long k = 1; k <= ticks; ++k)
  {
    loop->tick(k * loop->period());
    while (loop->samples().tryPop(&sample))
    {
    }
    while (loop->snapshots().tryPop(&snapshot))
    {
      double highest = -1.0;
      for (const BodyState& body : snapshot.bodies)
      {
        if (body.pose.translation().z() > highest)
        {
          highest = body.pose.translation().z();
          mug = body.pose;
        }
      }
    }
  }
  return mug;
}

// The mug's turn about the vertical (rad): the angle its x axis makes in the horizontal plane.
double yawOf(const Eigen::Isometry3d& pose)
{
  const Eigen::Vector3d x = pose.linear().col(0);
  return std::atan2(x.y(), x.x());
}

// The wrist turn (fake_hand's wrist_turn): held up, the hand turns 0.5 rad about the mug's axis
// and the oriented fingertips turn the mug with it, still held, without slipping; without the
// turn the mug does not turn.
TEST(HandLoop, FakeHandsWristTurnTurnsTheHeldMug)
{
  FakeHandParams params;
  params.wrist_turn = 0.5;
  const Eigen::Isometry3d turned = mugPoseAfter(params, 4400);  // turned by 4.2 s, held until 4.5
  params.wrist_turn = 0.0;
  const Eigen::Isometry3d still = mugPoseAfter(params, 4400);
  std::printf("mug at 4.4 s: turned %.6f rad at z %.4f m (wrist 0.5 rad); %.4f rad at z %.4f m (no turn)\n",
              yawOf(turned), turned.translation().z(), yawOf(still), still.translation().z());
  EXPECT_GT(turned.translation().z(), 0.08);
  EXPECT_NEAR(yawOf(turned), 0.5, 0.01);
  EXPECT_LT(std::abs(yawOf(still)), 0.02);
  EXPECT_GT(still.translation().z(), 0.08);
  // 3-DOF fingertips (orientation none) carry it most of the way (measured: 0.40 of the 0.5 rad;
  // the oriented pads 0.49999), still held.
  params.wrist_turn = 0.5;
  params.oriented = false;
  const Eigen::Isometry3d points = mugPoseAfter(params, 4400);
  std::printf("3-DOF fingertips: turned %.6f rad at z %.4f m\n", yawOf(points), points.translation().z());
  EXPECT_GT(yawOf(points), 0.3);
  EXPECT_LT(yawOf(points), 0.5 + 0.01);
  EXPECT_GT(points.translation().z(), 0.08);
}

TEST(HandLoop, FakeHandGraspsAndLiftsTheMug)
{
  // The mug's origin starts 0.5 mm above the table: carried up ~10 cm by a thumb and 2 or 4 fingers.
  EXPECT_GT(mugHeightAfterLift(2), 0.08);
  EXPECT_GT(mugHeightAfterLift(4), 0.08);
  EXPECT_GT(mugHeightAfterLift(2, false), 0.08);  // 3-DOF fingers (orientation: none)
}
}  // namespace
}  // namespace god_finger
