// The one coupling function: the spring-damper, its saturation (direction kept), and the
// profile's ranges.
#include "god_finger/haptics/virtual_coupling.h"

#include <gtest/gtest.h>

namespace god_finger
{
namespace
{
TEST(VirtualCoupling, SpringAndDamperPullTheProxyTowardsTheInterface)
{
  CouplingProfile profile;  // 400 N/m, 4 N s/m, 20 N
  const CouplingForce force = couplingForce(profile, Eigen::Vector3d(0, 0, -0.01), Eigen::Vector3d(0, 0, -0.1),
                                            Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 0.1));
  EXPECT_NEAR(force.on_proxy.z(), 400 * -0.01 + 4 * -0.2, 1e-12);
  EXPECT_EQ(force.on_proxy.x(), 0.0);
  EXPECT_FALSE(force.saturated);
}

TEST(VirtualCoupling, SaturatesAtMaxForceKeepingTheDirection)
{
  CouplingProfile profile;
  profile.max_force = 3.3;
  const CouplingForce force = couplingForce(profile, Eigen::Vector3d(0.03, 0.04, 0), Eigen::Vector3d::Zero(),
                                            Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  EXPECT_TRUE(force.saturated);
  EXPECT_NEAR(force.on_proxy.norm(), 3.3, 1e-12);
  EXPECT_NEAR(force.on_proxy.x() / force.on_proxy.y(), 0.75, 1e-12);
}

TEST(VirtualCoupling, ProfileRangesNameTheParameter)
{
  CouplingProfile profile;
  EXPECT_EQ(validate(profile), "");
  profile.stiffness = 0.0;
  EXPECT_EQ(validate(profile), "parameter 'coupling_stiffness' = 0 is out of range (0, 100000] (N/m)");
  profile = CouplingProfile();
  profile.damping = -1.0;
  EXPECT_EQ(validate(profile), "parameter 'coupling_damping' = -1 is out of range [0, 1000] (N s/m)");
  profile = CouplingProfile();
  profile.max_force = NAN;
  EXPECT_EQ(validate(profile), "parameter 'max_force' = nan is out of range (0, 10000] (N)");
}
}  // namespace
}  // namespace god_finger
