// The pad's shape under uniform pressure (src/physics/solver/pad_geometry.h), a private piece of the
// physics tested on its own: sub-god-objects on a circle of radius a give the disk's levers,
// (2/3) a and a, a pad pushed to one side moves its centre of pressure
// that way, and fewer than three points are a point.
#include "solver/pad_geometry.h"

#include <gtest/gtest.h>

#include <cmath>

namespace god_finger
{
using namespace internal;  // the private pieces under test
namespace
{
WorldContactArea ring(const Eigen::Vector3d& centre, double radius, int count, double stretch_x = 1.0)
{
  WorldContactArea area;
  area.point = centre;
  area.normal = Eigen::Vector3d::UnitZ();
  area.radius = radius;
  area.sub_god_object_count = count;
  for (int i = 0; i < count; ++i)
  {
    const double angle = 2.0 * M_PI * i / count;
    const double x = std::cos(angle) * radius;
    area.positions[i] = centre + Eigen::Vector3d((x > 0.0 ? stretch_x : 1.0) * x, std::sin(angle) * radius, 0.0);
  }
  return area;
}

TEST(PadGeometry, ARingOfSubGodObjectsGivesTheDisksLevers)
{
  const double a = 0.01;
  const Eigen::Vector3d centre(0.1, -0.2, 0.3);
  const PadGeometry pad = padGeometry(centre, Eigen::Vector3d::UnitZ(), ring(centre, a, 64));
  EXPECT_NEAR((pad.centre_of_pressure - centre).norm(), 0.0, 1e-12);
  // Each fan triangle is taken as a circular sector about its apex: a regular polygon of points on
  // the circle gives the disk's (2/3) a and a exactly, for 64 points as for the default 8.
  EXPECT_NEAR(pad.torsional_lever, 2.0 / 3.0 * a, 1e-15);
  EXPECT_NEAR(pad.support_radius, a, 1e-15);
  const PadGeometry octagon = padGeometry(centre, Eigen::Vector3d::UnitZ(), ring(centre, a, 8));
  EXPECT_NEAR(octagon.torsional_lever, 2.0 / 3.0 * a, 1e-15);
  EXPECT_NEAR(octagon.support_radius, a, 1e-15);
}

TEST(PadGeometry, APadSpreadToOneSideMovesItsCentreOfPressureThatWay)
{
  const Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  // The +x half reaches twice as far (Eq. 2's spread against a tangential force).
  const PadGeometry pad = padGeometry(centre, Eigen::Vector3d::UnitZ(), ring(centre, 0.01, 32, 2.0));
  EXPECT_GT(pad.centre_of_pressure.x(), 0.002);
  EXPECT_NEAR(pad.centre_of_pressure.y(), 0.0, 1e-12);
  EXPECT_NEAR(pad.centre_of_pressure.z(), 0.0, 1e-12);  // in the tangent plane
}

TEST(PadGeometry, FewerThanThreeSubGodObjectsAreAPoint)
{
  const Eigen::Vector3d centre(0.0, 0.0, 0.05);
  for (int count : {0, 1, 2})
  {
    const PadGeometry pad = padGeometry(centre, Eigen::Vector3d::UnitZ(), ring(centre, 0.01, count));
    EXPECT_EQ(pad.centre_of_pressure, centre) << count;
    EXPECT_EQ(pad.torsional_lever, 0.0) << count;
    EXPECT_EQ(pad.support_radius, 0.0) << count;
  }
}
}  // namespace
}  // namespace god_finger
