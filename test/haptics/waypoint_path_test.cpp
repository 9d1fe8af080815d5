// WaypointPath: straight lines between timed waypoints, held before and after; bad lists named.
#include "god_finger/haptics/waypoint_path.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace god_finger
{
namespace
{
TEST(WaypointPath, InterpolatesAndHolds)
{
  const WaypointPath path({{1.0, Eigen::Vector3d(0, 0, 0)}, {3.0, Eigen::Vector3d(2, 4, -2)}});
  EXPECT_EQ(path.at(0.0), Eigen::Vector3d(0, 0, 0));
  EXPECT_EQ(path.at(2.0), Eigen::Vector3d(1, 2, -1));
  EXPECT_EQ(path.at(9.0), Eigen::Vector3d(2, 4, -2));
  EXPECT_EQ(path.endTime(), 3.0);
}

TEST(WaypointPath, RejectsEmptyNonFiniteAndUnorderedLists)
{
  EXPECT_THROW(WaypointPath(std::vector<Waypoint>{}), InputError);
  EXPECT_THROW(WaypointPath({{0.0, Eigen::Vector3d(NAN, 0, 0)}}), InputError);
  try
  {
    WaypointPath({{0.0, Eigen::Vector3d::Zero()}, {0.0, Eigen::Vector3d::Ones()}});
    FAIL() << "no error";
  }
  catch (const InputError& error)
  {
    EXPECT_NE(std::string(error.what()).find("waypoint 1 at t = 0"), std::string::npos) << error.what();
  }
}
}  // namespace
}  // namespace god_finger
