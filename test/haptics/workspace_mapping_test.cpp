// WorkspaceMapping: device to world and back, forces rotated back, and the passivity claim of
// its header (force_scale = scale makes the world's work equal the hand's).
#include "god_finger/haptics/workspace_mapping.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

namespace god_finger
{
namespace
{
WorkspaceMappingParams turnedAndScaled()
{
  WorkspaceMappingParams params;
  params.scale = 2.5;
  params.force_scale = 2.5;
  params.offset = Eigen::Vector3d(0.1, -0.2, 0.3);
  params.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  return params;
}

TEST(WorkspaceMapping, IdentityByDefault)
{
  const WorkspaceMapping mapping(WorkspaceMappingParams{});
  const Eigen::Vector3d p(0.01, -0.02, 0.03);
  EXPECT_EQ(mapping.toWorld(p), p);
  EXPECT_EQ(mapping.forceToDevice(p), p);
}

TEST(WorkspaceMapping, RoundTripAndKnownRotation)
{
  const WorkspaceMapping mapping(turnedAndScaled());
  const Eigen::Vector3d p(0.03, 0.01, -0.02);
  EXPECT_LT((mapping.toDevice(mapping.toWorld(p)) - p).norm(), 1e-15);
  WorkspaceMappingParams quarter;
  quarter.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  const WorkspaceMapping turn(quarter);
  // Device x (away from the user) becomes world y.
  EXPECT_LT((turn.toWorld(Eigen::Vector3d::UnitX()) - Eigen::Vector3d::UnitY()).norm(), 1e-15);
  EXPECT_LT((turn.forceToDevice(Eigen::Vector3d::UnitY()) - Eigen::Vector3d::UnitX()).norm(), 1e-15);
}

TEST(WorkspaceMapping, PassiveWhenForceScaleEqualsScale)
{
  const WorkspaceMapping mapping(turnedAndScaled());
  const Eigen::Vector3d device_step(1e-3, -2e-3, 0.5e-3);
  const Eigen::Vector3d world_force(1.0, 2.0, -3.0);
  const double world_work = world_force.dot(mapping.velocityToWorld(device_step));
  const double hand_work = mapping.forceToDevice(world_force).dot(device_step);
  EXPECT_NEAR(world_work, hand_work, 1e-15);
}

TEST(WorkspaceMapping, APowerAtTheDeviceIsTheWorldsPowerOfTheSameMotionAndForce)
{
  WorkspaceMappingParams params = turnedAndScaled();
  params.force_scale = 0.25;  // not the passive mapping: the world sees scale / force_scale times the hand's power
  const WorkspaceMapping mapping(params);
  const Eigen::Vector3d device_velocity(0.1, -0.2, 0.05);
  const Eigen::Vector3d world_force(1.0, 2.0, -3.0);
  const double world_power = world_force.dot(mapping.velocityToWorld(device_velocity));
  const double device_power = mapping.forceToDevice(world_force).dot(device_velocity);
  EXPECT_NEAR(mapping.powerToWorld(device_power), world_power, 1e-14);
  EXPECT_NEAR(world_power / device_power, params.scale / 0.25, 1e-12);
}

TEST(WorkspaceMapping, BadParametersAreNamed)
{
  WorkspaceMappingParams params;
  params.scale = 0.0;
  EXPECT_EQ(validate(params), "parameter 'workspace_scale' = 0 is out of range (0, 1000] (dimensionless)");
  params = WorkspaceMappingParams();
  params.rotation = Eigen::Quaterniond(2, 0, 0, 0);
  EXPECT_NE(validate(params).find("parameter 'workspace_rotation' must be a unit quaternion"), std::string::npos);
  params = WorkspaceMappingParams();
  params.offset.x() = NAN;
  EXPECT_THROW(WorkspaceMapping{params}, InputError);
}
}  // namespace
}  // namespace god_finger
