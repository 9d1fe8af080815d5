// A three-finger hand lifts a mug mesh (scenarios/mug_grasp_task.h): friction against the weight
// decides whether it holds, and a shaking hand tilts it between points but not between pads.
#include "god_finger/support/input_error.h"
#include "god_finger/scenarios/mug_grasp_task.h"
#include "god_finger/scenarios/pad_fidelity.h"

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

MugGraspResult grasp(const PadLayout& layout, double squeeze, const OperatorTraits& hand = perfectOperator())
{
  MugGraspOptions options;
  options.scenes_dir = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes";
  options.model = layout.model;
  options.params.pad_solver = layout.pad_solver;
  options.squeeze = squeeze;
  options.hand = hand;
  const MugGraspResult r = runMugGrasp(options);
  std::printf(
      "[ mug %-17s squeeze %.1f mm ] held %d lifted %d, height %.4f m, tilt %.4f rad, slip %.5f m, "
      "grip %.3f N\n",
      layout.name, squeeze * 1e3, r.held, r.lifted, r.lift_height_m, r.max_tilt_rad, r.max_slip_m, r.mean_grip_force_N);
  return r;
}

TEST(MugGrasp, APerfectHandLiftsItStraight)
{
  const MugGraspResult r = grasp(kPad, 0.004);
  EXPECT_TRUE(r.held);
  EXPECT_TRUE(r.lifted);
  // The hand rises kMugLift; the mug hangs 2.5 mm lower on the coupling's vertical stretch.
  EXPECT_NEAR(r.lift_height_m, kMugLift, 0.004);
  EXPECT_LT(r.max_tilt_rad, 1e-3);
  EXPECT_LT(r.max_slip_m, 1e-4);
  // The coupling's squeeze, k s = 400 N/m x 4 mm, a little more on the decomposition's hull.
  EXPECT_NEAR(r.mean_grip_force_N, 1.6, 0.25);
}

TEST(MugGrasp, ATooLightSqueezeDropsIt)
{
  // 0.8 N per finger, mu 0.8: 1.9 N of friction against 2.94 N of weight. It stays on the table.
  const MugGraspResult r = grasp(kPad, 0.002);
  EXPECT_FALSE(r.held);
  EXPECT_FALSE(r.lifted);
  EXPECT_LT(std::abs(r.lift_height_m), 0.005);
}

TEST(MugGrasp, AShakingHandTiltsItBetweenPointsNotBetweenPads)
{
  const OperatorTraits hand = drawOperator(5, Eigen::Vector3d::UnitX());
  const MugGraspResult point = grasp(kPoint, 0.004, hand);
  const MugGraspResult pad = grasp(kPad, 0.004, hand);
  EXPECT_TRUE(point.held);
  EXPECT_GT(point.max_tilt_rad, kMugTiltTolerance);
  EXPECT_FALSE(point.lifted);
  EXPECT_TRUE(pad.lifted);
  EXPECT_LT(pad.max_tilt_rad, 0.01);
}

TEST(MugGrasp, ABadSqueezeIsRefused)
{
  MugGraspOptions options;
  options.scenes_dir = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes";
  options.squeeze = 0.0;
  EXPECT_THROW(runMugGrasp(options), InputError);
  options.squeeze = 0.04;
  EXPECT_THROW(runMugGrasp(options), InputError);
}
}  // namespace
}  // namespace god_finger
