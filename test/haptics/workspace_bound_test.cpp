// The workspace bound (haptics/workspace_bound.h): inside, the reading passes exactly with no force;
// outside, it is clamped onto the sphere and the wall pushes the hand back with the coupling's
// stiffness as the device feels it through the mapping.
#include "god_finger/haptics/workspace_bound.h"

#include <gtest/gtest.h>

#include <cmath>

namespace god_finger
{
namespace
{
TEST(WorkspaceBound, InsideIsUntouched)
{
  DeviceProfile profile;
  profile.workspace_radius = 0.1;
  const Eigen::Vector3d p(0.03, -0.04, 0.08);  // |p| = 0.094 m
  const WorkspaceBound bound = boundToWorkspace(p, profile, WorkspaceMapping());
  EXPECT_FALSE(bound.outside);
  EXPECT_EQ(bound.position, p);
  EXPECT_EQ(bound.wall_force, Eigen::Vector3d::Zero());
}

TEST(WorkspaceBound, TwiceTheRadiusIsClampedAndPushedBack)
{
  DeviceProfile profile;
  profile.workspace_radius = 0.05;
  profile.coupling.stiffness = 400.0;
  WorkspaceMappingParams mapping;
  mapping.scale = 2.0;
  mapping.force_scale = 0.5;
  const Eigen::Vector3d p(0.06, 0.0, 0.08);  // |p| = 0.1 = 2 R
  const WorkspaceBound bound = boundToWorkspace(p, profile, WorkspaceMapping(mapping));
  EXPECT_TRUE(bound.outside);
  EXPECT_NEAR(bound.position.norm(), 0.05, 1e-15);
  EXPECT_TRUE(bound.position.isApprox(p / 2.0));
  // k_c scale force_scale = 400 N/m, 5 cm past the wall: 20 N back toward the centre.
  EXPECT_TRUE(bound.wall_force.isApprox(-400.0 * (p - p / 2.0)));
  EXPECT_NEAR(bound.wall_force.norm(), 20.0, 1e-9);
  EXPECT_LT(bound.wall_force.dot(p), 0.0);
}

TEST(WorkspaceBound, NonFiniteReadingsPassForTheCallerToReject)
{
  DeviceProfile profile;
  const WorkspaceBound bound = boundToWorkspace(Eigen::Vector3d(NAN, 0, 1), profile, WorkspaceMapping());
  EXPECT_FALSE(bound.outside);
  EXPECT_EQ(bound.wall_force, Eigen::Vector3d::Zero());
}
}  // namespace
}  // namespace god_finger
