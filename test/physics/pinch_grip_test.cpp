// A two-finger pinch of a bar across its parallel faces, gripped off its centre and lifted:
// how far it turns, and whether it stays in the grip, as the squeeze grows. Scene: a static
// table and a bar of 0.2 x 0.03 x 0.04 m (150 g, mu 0.8) lying on it; the fingers close along
// y on the 3 cm faces, 3 cm off the bar's centre along x, the second one misaligned by d along
// x and d / 2 along z (a human hand's offset); the coupling stretch (the squeeze) s gives
// N = k s with k = 400 N/m; they lift it 10 cm in 2 s and hold 2.5 s. Deterministic (fixed
// step, no randomness).
#include "god_finger/physics/god_finger_world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace god_finger
{
namespace
{
constexpr double kBarMass = 0.15;     // kg
constexpr double kGripOffset = 0.03;  // m, from the bar's centre along x
constexpr double kBarWidth = 0.03;    // m, between the pinched faces (y)
constexpr double kLift = 0.1;         // m

SceneDescription barScene()
{
  SceneDescription scene;
  BodyDescription table;
  table.name = "table";
  table.is_static = true;
  table.geometry.kind = GeometryKind::kBox;
  table.geometry.size = Eigen::Vector3d(0.6, 0.6, 0.04);
  table.pose.translation() = Eigen::Vector3d(0, 0, -0.02);
  BodyDescription bar;
  bar.name = "bar";
  bar.mass = kBarMass;
  bar.geometry.kind = GeometryKind::kBox;
  const Eigen::Vector3d size(0.2, kBarWidth, 0.04);
  bar.geometry.size = size;
  bar.pose.translation() = Eigen::Vector3d(0, 0, 0.02);
  const Eigen::Vector3d squared = size.cwiseProduct(size);
  bar.inertia = (kBarMass / 12.0 *
                 Eigen::Vector3d(squared.y() + squared.z(), squared.x() + squared.z(), squared.x() + squared.y()))
                    .asDiagonal();
  scene.bodies = {table, bar};
  return scene;
}

struct Grip
{
  double turn = 0.0;      // rad, about the pinch normal (y) at the end
  double max_turn = 0.0;  // rad, the largest after the lift started
  double max_tilt = 0.0;  // rad, the largest about the other axes
  bool held = false;      // the bar's centre ends above half the lift height (the scenarios' rule)
};

Grip pinchBar(ContactModel model, double squeeze, double misalignment, const WorldParams& params)
{
  const SceneDescription scene = barScene();
  GodFingerWorld world(scene, params);
  world.setContactModel(model);
  const int bar = scene.find("bar");
  const double z = 0.02;
  const Eigen::Vector3d offset(misalignment, 0.0, 0.5 * misalignment);
  const double open = 0.04;
  const double face = 0.5 * kBarWidth + params.coupling.proxy_radius;  // proxy centre on the face
  const int near = world.addInterface(Eigen::Vector3d(kGripOffset, -open, z));
  const int far = world.addInterface(Eigen::Vector3d(kGripOffset, open, z) + offset);
  const Eigen::Matrix3d start = world.bodyState(bar).pose.linear();
  const double start_z = world.bodyState(bar).center_of_mass.z();
  const double dt = world.params().time_step;
  Grip grip;
  for (long i = 0; i < std::lround(6.0 / dt); ++i)
  {
    const double t = (i + 1) * dt;
    const double y = open + (face - squeeze - open) * std::min(1.0, t / 1.0);
    const double lift = t < 1.5 ? 0.0 : kLift * std::min(1.0, (t - 1.5) / 2.0);
    world.setInterfaceTarget(near, Eigen::Vector3d(kGripOffset, -y, z + lift));
    world.setInterfaceTarget(far, Eigen::Vector3d(kGripOffset, y, z + lift) + offset);
    world.step();
    if (t > 1.5)
    {
      const Eigen::AngleAxisd turned(world.bodyState(bar).pose.linear() * start.transpose());
      const Eigen::Vector3d rotation = turned.angle() * turned.axis();
      grip.turn = std::abs(rotation.y());
      grip.max_turn = std::max(grip.max_turn, grip.turn);
      grip.max_tilt = std::max(grip.max_tilt, std::hypot(rotation.x(), rotation.z()));
    }
  }
  grip.held = world.bodyState(bar).center_of_mass.z() > start_z + 0.5 * kLift;
  return grip;
}

void print(const char* what, ContactModel model, double squeeze, double misalignment, const Grip& grip)
{
  std::printf("[ pinch %-11s %-12s s %2.0f mm d %2.0f mm ] turn %.4f rad (max %.4f), tilt %.4f rad, %s\n", what,
              contactModelName(model), squeeze * 1e3, misalignment * 1e3, grip.turn, grip.max_turn, grip.max_tilt,
              grip.held ? "held" : "lost");
}

// The finding: soft_finger turned the bar more with more squeeze and lost it at 30 mm.
// With the pad's tilt lever, more squeeze never turns it more and it never drops; god_finger
// likewise.
TEST(PinchGrip, MoreSqueezeNeverTurnsTheBarMoreNorDropsIt)
{
  for (const ContactModel model : {ContactModel::kSoftFinger, ContactModel::kGodFinger})
  {
    for (const double misalignment : {0.003, 0.01})
    {
      double previous_turn = INFINITY;
      for (const double squeeze : {0.012, 0.02, 0.03, 0.05})
      {
        SCOPED_TRACE(std::string(contactModelName(model)) + " s " + std::to_string(squeeze) + " d " +
                     std::to_string(misalignment));
        const Grip grip = pinchBar(model, squeeze, misalignment, WorldParams());
        print("", model, squeeze, misalignment, grip);
        EXPECT_TRUE(grip.held);
        EXPECT_LE(grip.max_turn, previous_turn + 1e-3);
        EXPECT_LT(grip.max_tilt, 0.05);
        previous_turn = grip.max_turn;
      }
    }
  }
}

// Why it misbehaved: a point that resists no tilt (the lever of Bullet's default, 1e-4 m) holds
// the misaligned pinch's couple N d only with friction, which drags the coupled proxies apart
// and grows d by 2 s / w per round: stable below s = w / 2 = 15 mm, lost above.
TEST(PinchGrip, WithoutATiltLeverThePinchIsUnstableBeyondHalfTheWidth)
{
  WorldParams point;
  point.soft_finger.rolling_friction = 1e-4;
  const Grip below = pinchBar(ContactModel::kSoftFinger, 0.012, 0.003, point);
  const Grip above = pinchBar(ContactModel::kSoftFinger, 0.03, 0.003, point);
  print("point", ContactModel::kSoftFinger, 0.012, 0.003, below);
  print("point", ContactModel::kSoftFinger, 0.03, 0.003, above);
  EXPECT_TRUE(below.held);
  EXPECT_LT(below.max_tilt, 0.5);
  EXPECT_GT(above.max_tilt, 1.0);
}

// Below the twist limit the bar turns as physics says: until the gravity torque about the
// pinch normal, m g x cos(turn), falls to the two contacts' limit 2 spinning_friction mu N.
TEST(PinchGrip, BelowTheTwistLimitTheBarTurnsToWhereGravityMeetsTheLimit)
{
  const WorldParams params;
  const double squeeze = 0.004;
  const double normal_force = CouplingProfile().stiffness * squeeze;
  const double limit = 2.0 * params.soft_finger.spinning_friction * 0.8 * normal_force;
  const double gravity_torque = kBarMass * 9.81 * kGripOffset;
  ASSERT_LT(limit, gravity_torque);
  const double expected = std::acos(limit / gravity_torque);
  const Grip grip = pinchBar(ContactModel::kSoftFinger, squeeze, 0.003, params);
  print("", ContactModel::kSoftFinger, squeeze, 0.003, grip);
  std::printf("[ pinch twist limit ] %.4f N m against gravity's %.4f N m: turn %.3f rad, expected at least %.3f\n",
              limit, gravity_torque, grip.turn, expected);
  EXPECT_TRUE(grip.held);
  EXPECT_GT(grip.turn, expected - 0.05);
  EXPECT_LT(grip.turn, expected + 0.3);
}
}  // namespace
}  // namespace god_finger
