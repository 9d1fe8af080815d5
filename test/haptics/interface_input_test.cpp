// The interface-input pipeline both topologies share (haptics/interface_input.h): a reading is
// bounded and mapped, a non-finite one changes nothing, presses are edges, and an unusable
// orientation keeps the last usable one.
#include "god_finger/haptics/interface_input.h"

#include <gtest/gtest.h>

#include <cmath>

namespace god_finger
{
namespace
{
InterfaceInput scaledInput()
{
  DeviceProfile profile;
  profile.workspace_radius = 0.05;
  profile.coupling.stiffness = 400.0;
  WorkspaceMappingParams params;
  params.scale = 2.0;
  params.force_scale = 0.5;
  params.offset = Eigen::Vector3d(0.0, 0.0, 0.3);
  return InterfaceInput(profile, WorkspaceMapping(params));
}

InterfaceReading at(const Eigen::Vector3d& position, std::uint32_t buttons = 0)
{
  InterfaceReading reading;
  reading.position = position;
  reading.buttons = buttons;
  return reading;
}

TEST(InterfaceInput, BoundsThenMapsIntoTheWorld)
{
  InterfaceInput input = scaledInput();
  const InterfaceInputResult inside = input.read(at(Eigen::Vector3d(0.01, -0.02, 0.03)));
  ASSERT_TRUE(inside.accepted);
  EXPECT_TRUE(inside.target.isApprox(Eigen::Vector3d(0.02, -0.04, 0.36)));
  EXPECT_EQ(inside.wall_force, Eigen::Vector3d::Zero());
  // 10 cm out along x: clamped at 5 cm (world 0.1 m), the wall pushes back 400 N/m * 5 cm.
  const InterfaceInputResult outside = input.read(at(Eigen::Vector3d(0.1, 0.0, 0.0)));
  ASSERT_TRUE(outside.accepted);
  EXPECT_TRUE(outside.target.isApprox(Eigen::Vector3d(0.1, 0.0, 0.3)));
  EXPECT_NEAR(outside.wall_force.x(), -20.0, 1e-9);
}

TEST(InterfaceInput, ANonFiniteReadingIsRejectedWholeAndChangesNothing)
{
  InterfaceInput input = scaledInput();
  ASSERT_TRUE(input.read(at(Eigen::Vector3d::Zero(), 1u)).accepted);
  InterfaceReading bad = at(Eigen::Vector3d(NAN, 0.0, 0.0), 3u);
  EXPECT_FALSE(input.read(bad).accepted);
  bad = at(Eigen::Vector3d::Zero(), 3u);
  bad.velocity.y() = INFINITY;
  EXPECT_FALSE(input.read(bad).accepted);
  // The rejected presses of button 1 never counted: the next good reading still presses it once.
  EXPECT_EQ(input.read(at(Eigen::Vector3d::Zero(), 3u)).pressed, kButtonReset);
}

TEST(InterfaceInput, PressesAreEdges)
{
  InterfaceInput input = scaledInput();
  EXPECT_EQ(input.read(at(Eigen::Vector3d::Zero(), kButtonCycleModel)).pressed, kButtonCycleModel);
  EXPECT_EQ(input.read(at(Eigen::Vector3d::Zero(), kButtonCycleModel)).pressed, 0u);  // held
  EXPECT_EQ(input.read(at(Eigen::Vector3d::Zero(), 0u)).pressed, 0u);                 // released
  EXPECT_EQ(input.read(at(Eigen::Vector3d::Zero(), kButtonCycleModel | kButtonStopForce)).pressed,
            kButtonCycleModel | kButtonStopForce);
}

TEST(InterfaceInput, AnUnusableOrientationKeepsTheLastUsableOne)
{
  WorkspaceMappingParams params;
  params.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  InterfaceInput input{DeviceProfile(), WorkspaceMapping(params)};
  InterfaceReading reading = at(Eigen::Vector3d::Zero());
  EXPECT_EQ(input.read(reading).orientation, OrientationInput::kNone);
  EXPECT_FALSE(input.oriented());
  reading.has_orientation = true;
  reading.orientation = Eigen::Quaterniond(2.0, 0.0, 0.0, 0.0);  // norm 2: usable, normalised
  EXPECT_EQ(input.read(reading).orientation, OrientationInput::kUsable);
  ASSERT_TRUE(input.oriented());
  EXPECT_NEAR(input.deviceOrientation().w(), 1.0, 1e-15);
  // In the world: the mapping's rotation, a quarter turn about z.
  EXPECT_NEAR(input.worldOrientation().angularDistance(params.rotation), 0.0, 1e-12);
  reading.orientation = Eigen::Quaterniond(NAN, 0.0, 0.0, 0.0);
  const InterfaceInputResult rejected = input.read(reading);
  EXPECT_TRUE(rejected.accepted);  // the position is taken
  EXPECT_EQ(rejected.orientation, OrientationInput::kRejected);
  EXPECT_TRUE(input.oriented());
  EXPECT_NEAR(input.worldOrientation().angularDistance(params.rotation), 0.0, 1e-12);
}
}  // namespace
}  // namespace god_finger
