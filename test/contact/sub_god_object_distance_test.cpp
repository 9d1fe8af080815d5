// The tilt-corrected sub-god-object distance (contact/sub_god_object_distance.h).
#include "god_finger/contact/sub_god_object_distance.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

namespace god_finger
{
namespace
{
const Eigen::Vector3d kUp(0, 0, 1);

TEST(SubGodObjectDistance, WithoutTiltEveryPointHasTheContactsDistance)
{
  for (const Eigen::Vector3d& lever : {Eigen::Vector3d(0.01, 0, 0), Eigen::Vector3d(-0.003, 0.004, 0)})
  {
    EXPECT_EQ(tiltCorrectedDistance(-0.0002, kUp, Eigen::Matrix3d::Identity(), lever), -0.0002);
  }
  // A turn about the normal moves the point within the pad's plane: no change either.
  const Eigen::Matrix3d twist = Eigen::AngleAxisd(0.3, kUp).toRotationMatrix();
  EXPECT_NEAR(tiltCorrectedDistance(-0.0002, kUp, twist, Eigen::Vector3d(0.01, 0, 0)), -0.0002, 1e-18);
}

TEST(SubGodObjectDistance, ATiltRaisesOneSideAndLowersTheOther)
{
  // The object turned by theta about x relative to the pad: a point at y = +L moved by
  // L sin(theta) along the normal, the point at y = -L by -L sin(theta).
  const double theta = 0.05;
  const double length = 0.008;
  const Eigen::Matrix3d tilt = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitX()).toRotationMatrix();
  EXPECT_NEAR(tiltCorrectedDistance(0.0, kUp, tilt, Eigen::Vector3d(0, length, 0)), length * std::sin(theta), 1e-15);
  EXPECT_NEAR(tiltCorrectedDistance(0.0, kUp, tilt, Eigen::Vector3d(0, -length, 0)), -length * std::sin(theta), 1e-15);
  // Points on the tilt's axis keep the contact's distance.
  EXPECT_NEAR(tiltCorrectedDistance(-0.001, kUp, tilt, Eigen::Vector3d(length, 0, 0)), -0.001, 1e-18);
}
}  // namespace
}  // namespace god_finger
