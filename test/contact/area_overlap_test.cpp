// Overlap of two contact areas (contact/area_overlap.h): the lens area against its closed forms, and
// which pairs of areas overlap (same side, a pad wrapped onto the other's face, never across a wall).
#include "god_finger/contact/area_overlap.h"

#include <gtest/gtest.h>

#include <cmath>

namespace god_finger
{
namespace
{
AreaDisk disk(const Eigen::Vector3d& centre, const Eigen::Vector3d& normal, double radius, double reach)
{
  AreaDisk result;
  result.centre = centre;
  result.normal = normal.normalized();
  result.radius = radius;
  result.reach = reach;
  return result;
}

TEST(LensArea, CoincidentDisksShareTheWholeDisk)
{
  EXPECT_NEAR(lensArea(0.01, 0.01, 0.0), M_PI * 1e-4, 1e-15);
}

TEST(LensArea, TangentAndSeparateDisksShareNothing)
{
  EXPECT_EQ(lensArea(0.01, 0.005, 0.015), 0.0);
  EXPECT_EQ(lensArea(0.01, 0.005, 0.02), 0.0);
  // Just inside tangency: a sliver, positive and tiny.
  const double sliver = lensArea(0.01, 0.005, 0.015 - 1e-6);
  EXPECT_GT(sliver, 0.0);
  EXPECT_LT(sliver, 1e-9);
}

TEST(LensArea, EqualDisksOneRadiusApartMatchTheClosedForm)
{
  // Two disks of radius r with centres r apart share r^2 (2 pi / 3 - sqrt(3) / 2).
  const double r = 0.008;
  EXPECT_NEAR(lensArea(r, r, r), r * r * (2.0 * M_PI / 3.0 - std::sqrt(3.0) / 2.0), 1e-15);
}

TEST(LensArea, HalfOverlapOfEqualDisks)
{
  // Equal disks whose centres are d apart: 2 r^2 acos(d / 2r) - (d / 2) sqrt(4 r^2 - d^2).
  const double r = 0.01;
  const double d = 0.0080795;  // about half of the disk: 2 acos(x) - 2 x sqrt(1 - x^2) = pi / 2
  const double expected = 2.0 * r * r * std::acos(d / (2.0 * r)) - 0.5 * d * std::sqrt(4.0 * r * r - d * d);
  EXPECT_NEAR(lensArea(r, r, d), expected, 1e-15);
  EXPECT_NEAR(lensArea(r, r, d) / (M_PI * r * r), 0.5, 1e-4);
}

TEST(LensArea, DifferentRadii)
{
  // r1 = 3, r2 = 4, d = 5 (a right angle at the chord's ends): the chord is 4.8 long, and the
  // lens is the two circular segments: r^2 (theta - sin theta) / 2 each.
  const double r1 = 0.003;
  const double r2 = 0.004;
  const double theta1 = 2.0 * std::asin(0.0024 / r1);
  const double theta2 = 2.0 * std::asin(0.0024 / r2);
  const double expected = 0.5 * r1 * r1 * (theta1 - std::sin(theta1)) + 0.5 * r2 * r2 * (theta2 - std::sin(theta2));
  EXPECT_NEAR(lensArea(r1, r2, 0.005), expected, 1e-15);
  EXPECT_NEAR(lensArea(r2, r1, 0.005), expected, 1e-15);
  // The small disk inside the large one.
  EXPECT_NEAR(lensArea(0.01, 0.004, 0.005), M_PI * 1.6e-5, 1e-15);
}

TEST(AreaOverlap, SameSideAreasOverlapByTheirLens)
{
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  const AreaOverlap overlap = areaOverlap(disk({0.0, 0.0, 0.0}, up, 0.01, 0.0), disk({0.01, 0.0, 0.0}, up, 0.01, 0.0));
  EXPECT_EQ(overlap.kind, OverlapKind::kSameSide);
  EXPECT_NEAR(overlap.area, 1e-4 * (2.0 * M_PI / 3.0 - std::sqrt(3.0) / 2.0), 1e-15);
  EXPECT_NEAR((overlap.direction - Eigen::Vector3d::UnitX()).norm(), 0.0, 1e-12);
}

TEST(AreaOverlap, NormalsTiltedWithinThirtyDegreesProjectOnTheMidPlane)
{
  // Both normals 20 degrees off z, in opposite directions (40 degrees apart: more than the
  // tolerance) do not overlap; 10 degrees each (20 apart) do, on the plane z = const.
  const double a10 = 10.0 * M_PI / 180.0;
  const double a20 = 20.0 * M_PI / 180.0;
  const Eigen::Vector3d left10(-std::sin(a10), 0.0, std::cos(a10));
  const Eigen::Vector3d right10(std::sin(a10), 0.0, std::cos(a10));
  const Eigen::Vector3d left20(-std::sin(a20), 0.0, std::cos(a20));
  const Eigen::Vector3d right20(std::sin(a20), 0.0, std::cos(a20));
  const AreaOverlap near =
      areaOverlap(disk({0.0, 0.0, 0.0}, left10, 0.01, 0.0), disk({0.01, 0.0, 0.0}, right10, 0.01, 0.0));
  EXPECT_EQ(near.kind, OverlapKind::kSameSide);
  EXPECT_NEAR(near.area, 1e-4 * (2.0 * M_PI / 3.0 - std::sqrt(3.0) / 2.0), 1e-15);
  const AreaOverlap far =
      areaOverlap(disk({0.0, 0.0, 0.0}, left20, 0.01, 0.0), disk({0.01, 0.0, 0.0}, right20, 0.01, 0.0));
  EXPECT_EQ(far.kind, OverlapKind::kNone);
  EXPECT_EQ(far.area, 0.0);
}

TEST(AreaOverlap, PadsOnOppositeFacesNeverOverlapHoweverThinTheWall)
{
  // A 2 mm plate between x = -0.001 and 0.001: one area on each face, 5 mm apart along y, and
  // pressed deep; and a 0.1 mm card with the two centres on one line. A pinch, not an overlap.
  const AreaOverlap pinched = areaOverlap(disk({-0.001, 0.0, 0.0}, -Eigen::Vector3d::UnitX(), 0.008, 0.004),
                                          disk({0.001, 0.005, 0.0}, Eigen::Vector3d::UnitX(), 0.008, 0.004));
  EXPECT_EQ(pinched.kind, OverlapKind::kNone);
  EXPECT_EQ(pinched.area, 0.0);
  EXPECT_EQ(pinched.direction, Eigen::Vector3d::Zero());
  const AreaOverlap card = areaOverlap(disk({-0.00005, 0, 0}, -Eigen::Vector3d::UnitX(), 0.01, 0.01),
                                       disk({0.00005, 0, 0}, Eigen::Vector3d::UnitX(), 0.01, 0.01));
  EXPECT_EQ(card.kind, OverlapKind::kNone);
  EXPECT_EQ(card.area, 0.0);
}

// A pad that wraps over a 45-degree chamfer onto the face another pad presses: only its points
// on that face, inside the other's disk, count.
TEST(AreaOverlap, AWrappedPadCountsOnlyItsPartOnTheOtherFace)
{
  const double r = 0.01;
  // b presses the top face (z = 0, normal z) at the origin. a presses the chamfer (normal 45
  // degrees between z and x) at x = 0.012; of its 8 points, 3 wrapped onto the top face, 2 of them
  // within b's disk.
  const AreaDisk b = disk({0, 0, 0}, Eigen::Vector3d::UnitZ(), r, 0.0);
  const Eigen::Vector3d points[] = {{0.008, 0.0, 0.0},       {0.009, 0.003, 0.0},    {0.011, -0.005, 0.0},
                                    {0.015, 0.0, -0.003},    {0.016, 0.004, -0.004}, {0.018, 0.0, -0.006},
                                    {0.014, -0.006, -0.002}, {0.017, -0.003, -0.005}};
  AreaDisk a = disk({0.012, 0.0, -0.001}, Eigen::Vector3d(1, 0, 1), r, 0.0);
  a.points = points;
  a.point_count = 8;
  const AreaOverlap overlap = areaOverlap(a, b);
  EXPECT_EQ(overlap.kind, OverlapKind::kWrapped);
  EXPECT_NEAR(overlap.area, M_PI * r * r * 2.0 / 9.0, 1e-15);
  EXPECT_NEAR(overlap.direction.norm(), 1.0, 1e-12);
  EXPECT_EQ(areaOverlap(b, a).area, overlap.area);
  // Without its wrapped points (a flat disk on the chamfer), nothing is shared.
  a.point_count = 0;
  EXPECT_EQ(areaOverlap(a, b).kind, OverlapKind::kNone);
  // A non-finite point is refused.
  Eigen::Vector3d bad[] = {{NAN, 0, 0}};
  a.points = bad;
  a.point_count = 1;
  EXPECT_EQ(areaOverlap(a, b).kind, OverlapKind::kNone);
}

TEST(AreaOverlap, PerpendicularOrDistantAreasDoNotOverlap)
{
  EXPECT_EQ(areaOverlap(disk({0, 0, 0}, Eigen::Vector3d::UnitZ(), 0.01, 0.01),
                        disk({0.001, 0, 0}, Eigen::Vector3d::UnitX(), 0.01, 0.01))
                .kind,
            OverlapKind::kNone);
  EXPECT_EQ(areaOverlap(disk({0, 0, 0}, Eigen::Vector3d::UnitZ(), 0.01, 0.0),
                        disk({0.025, 0, 0}, Eigen::Vector3d::UnitZ(), 0.01, 0.0))
                .area,
            0.0);
}

TEST(AreaOverlap, CoincidentCentresGetAFixedInPlaneDirection)
{
  const AreaOverlap overlap = areaOverlap(disk({0, 0, 0}, Eigen::Vector3d::UnitX(), 0.01, 0.002),
                                          disk({0.0005, 0, 0}, Eigen::Vector3d::UnitX(), 0.01, 0.002));
  EXPECT_EQ(overlap.kind, OverlapKind::kSameSide);
  EXPECT_NEAR(overlap.area, M_PI * 1e-4, 1e-15);
  EXPECT_NEAR(overlap.direction.norm(), 1.0, 1e-12);
  EXPECT_NEAR(overlap.direction.x(), 0.0, 1e-12);
}

TEST(AreaOverlap, NonFiniteInputIsNoOverlap)
{
  const AreaOverlap overlap = areaOverlap(disk({NAN, 0, 0}, Eigen::Vector3d::UnitZ(), 0.01, 0.0),
                                          disk({0, 0, 0}, Eigen::Vector3d::UnitZ(), 0.01, 0.0));
  EXPECT_EQ(overlap.kind, OverlapKind::kNone);
  EXPECT_EQ(overlap.area, 0.0);
}
}  // namespace
}  // namespace god_finger
