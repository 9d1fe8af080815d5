// Pinch and turn a cylinder 90 degrees (scenarios/cylinder_turn_task.h): a pad turns it with the
// fingers, a point (a ball that keeps its orientation) rolls on the mantle and swings it about
// the pinch line, a light squeeze drops it, and a 3-DOF pad resists the mantle's roll until the
// hand's pull, which a harder squeeze shortens, no longer overcomes it.
#include "god_finger/scenarios/cylinder_turn_task.h"
#include "god_finger/scenarios/pad_fidelity.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace god_finger
{
namespace
{
// kPadLayouts: god_object, soft_finger, god_finger (pad constraint), god_finger/points.
constexpr const PadLayout& kPoint = kPadLayouts[0];
constexpr const PadLayout& kPad = kPadLayouts[2];

CylinderTurnResult turn(const PadLayout& layout, double squeeze, const OperatorTraits& hand = perfectOperator(),
                        bool oriented = false)
{
  CylinderTurnOptions options;
  options.model = layout.model;
  options.params.pad_solver = layout.pad_solver;
  options.squeeze = squeeze;
  options.hand = hand;
  options.oriented = oriented;
  const CylinderTurnResult r = runCylinderTurn(options);
  std::printf(
      "[ turn %-17s squeeze %.1f mm%s ] held %d turned %d, turn %.4f rad, tilt %.4f (max %.4f) rad, slip "
      "%.5f m, grip %.3f N\n",
      layout.name, squeeze * 1e3, oriented ? " oriented" : "", r.held, r.turned, r.turn_rad, r.final_tilt_rad,
      r.max_tilt_rad, r.max_slip_m, r.mean_grip_force_N);
  return r;
}

TEST(CylinderTurn, APerfectHandTurnsItNinetyDegreesWithThePad)
{
  const CylinderTurnResult pad = turn(kPad, 0.005);
  EXPECT_TRUE(pad.held);
  EXPECT_TRUE(pad.turned);
  EXPECT_NEAR(pad.turn_rad, kTurnAngle, 0.05);
  EXPECT_LT(pad.max_tilt_rad, 0.01);
  EXPECT_LT(pad.max_slip_m, 0.003);
  // The coupling's squeeze: k s = 400 N/m x 5 mm.
  EXPECT_NEAR(pad.mean_grip_force_N, 2.0, 0.1);
}

TEST(CylinderTurn, APointRollsOnTheMantleAndLetsItSwingAboutThePinchLine)
{
  // A ball fingertip that keeps its orientation rolls without slipping: the mantle's point under
  // it moves with it, so the cylinder turns (r + proxy radius) / r times the fingers' angle.
  const double rolling = kTurnAngle * (kTurnCylinderRadius + WorldParams().coupling.proxy_radius) / kTurnCylinderRadius;
  const CylinderTurnResult point = turn(kPoint, 0.0025);
  EXPECT_TRUE(point.held);
  EXPECT_NEAR(point.turn_rad, rolling, 0.01);
  EXPECT_LT(point.max_slip_m, 0.002);
  // Nothing resists the turn about the line between two points: harder, it swings away.
  const CylinderTurnResult pressed = turn(kPoint, 0.01);
  EXPECT_GT(pressed.max_tilt_rad, 0.2);
  EXPECT_FALSE(pressed.turned);
  EXPECT_LT(turn(kPad, 0.01).max_tilt_rad, 0.001);
}

TEST(CylinderTurn, ATooLightSqueezeDropsIt)
{
  // 1 N per finger, mu 0.8: 1.6 N of friction against 1.47 N of weight, less once turning.
  const CylinderTurnResult light = turn(kPad, 0.0025);
  EXPECT_FALSE(light.held);
  EXPECT_FALSE(light.turned);
  EXPECT_GT(light.max_slip_m, 0.03);
}

TEST(CylinderTurn, APadThatCannotTurnResistsTheRollMoreTheHarderItPresses)
{
  // 3-DOF fingers keep their orientation: turning the cylinder rolls the mantle under the pads,
  // whose tilt rows (N x the area's radius) hold against it.
  const double light = turn(kPad, 0.005).turn_rad;
  const double firm = turn(kPad, 0.01).turn_rad;
  const double hard = turn(kPad, 0.02).turn_rad;
  EXPECT_GT(light, firm);
  EXPECT_GT(firm, hard);
  EXPECT_LT(hard, 0.7);
}

TEST(CylinderTurn, TheHandsPullNotFrictionStopsTheTurn)
{
  // Each finger's target goes round a circle of radius R - s about the axis (R = r + proxy
  // radius), so with the cylinder (and the pad stuck on it) lagging the target by `lag` the
  // coupling pulls the pad along the mantle with k (R - s) sin(lag): at most 5.2 N at 20 mm. The
  // turn stops where that pull's torque about the axis meets the pads' resistance to the roll,
  // N a_eff: a_eff is the tilt rows' area radius (r_max) plus the centre of pressure's shift, far
  // under mu r (24 mm), and friction (mu N) is never reached. Measured (perfect hand, 20 mm): turn
  // 0.6175 rad, lag 0.953 rad, pull 4.24 N, mean grip 9.73 N (10.24 N at the end), a_eff 13.1 mm
  // (12.4 mm at the end's grip: 10.2 mm tilt rows, 2.1 mm centre of pressure), slip 1.8 mm.
  const WorldParams params;
  const double squeeze = 0.02;
  const CylinderTurnResult hard = turn(kPad, squeeze);
  const double lag = kTurnAngle - hard.turn_rad;
  const double pull =
      params.coupling.stiffness * (kTurnCylinderRadius + params.coupling.proxy_radius - squeeze) * std::sin(lag);
  const double lever = pull * kTurnCylinderRadius / hard.mean_grip_force_N;
  std::printf("[ 20 mm: lag %.4f rad, pull %.3f N, a_eff %.2f mm ]\n", lag, pull, lever * 1e3);
  EXPECT_GT(lag, 0.8);
  EXPECT_GT(lever, params.contact.max_radius);
  EXPECT_LT(lever, 1.5 * params.contact.max_radius);
  EXPECT_LT(1.5 * params.contact.max_radius, kTurnCylinderFriction * kTurnCylinderRadius);
  EXPECT_LT(pull, 0.6 * kTurnCylinderFriction * hard.mean_grip_force_N);
  EXPECT_LT(hard.max_slip_m, 0.003);
}

TEST(CylinderTurn, OrientedFingersTurnItWithTheirPadsAtEverySqueeze)
{
  // The fingers turn with the hand and their pads with them (physics/solver/pad_state.h): the
  // cylinder turns exactly with them, however hard they squeeze (3-DOF: 1.60, 1.44 and 0.62 rad
  // at 5, 10 and 20 mm, above).
  for (const double squeeze : {0.005, 0.01, 0.02})
  {
    const CylinderTurnResult r = turn(kPad, squeeze, perfectOperator(), true);
    EXPECT_TRUE(r.turned) << squeeze;
    EXPECT_NEAR(r.turn_rad, kTurnAngle, 0.005) << squeeze;
    EXPECT_LT(r.max_tilt_rad, 0.005) << squeeze;
  }
  // A human-like hand (tremor, the wrist's too, misalignment, fluctuating squeeze, reflex) at
  // 20 mm, where a 3-DOF pad turns it 37 degrees (bench/REPORT.md section 10).
  const CylinderTurnResult human = turn(kPad, 0.02, drawOperator(1, Eigen::Vector3d::UnitY()), true);
  EXPECT_TRUE(human.turned);
  EXPECT_NEAR(human.turn_rad, kTurnAngle, 0.02);
  EXPECT_LT(human.max_tilt_rad, 0.02);
}

TEST(CylinderTurn, ABadSqueezeIsRefused)
{
  CylinderTurnOptions options;
  options.squeeze = 0.0;
  EXPECT_THROW(runCylinderTurn(options), InputError);
  options.squeeze = 0.06;
  EXPECT_THROW(runCylinderTurn(options), InputError);
}
}  // namespace
}  // namespace god_finger
