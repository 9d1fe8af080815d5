// Exact walks on spheres and cylinders (contact/primitive_walk.h) against the closed-form
// geodesics, their stops, and against the mesh walk on ever finer tessellations.
#include "god_finger/contact/primitive_walk.h"
#include "god_finger/geometry/mesh_primitives.h"
#include "god_finger/geometry/surface_locator.h"
#include "god_finger/geometry/triangle_mesh.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <cmath>

namespace god_finger
{
namespace
{
WalkLimits limitsFor(const Eigen::Vector3d& normal, double max_angle = M_PI / 3.0, double friction = INFINITY)
{
  ContactParams params;
  params.max_angle = max_angle;
  params.friction = friction;
  return makeWalkLimits(params, normal, 1.0);
}

TEST(PrimitiveWalk, SphereWalksGreatCirclesAndStopsAtTauAOrTheFrictionCone)
{
  const PrimitiveSurface sphere{PrimitiveSurface::Kind::kSphere, 0.04, 0.0};
  const Eigen::Vector3d top(0.0, 0.0, 0.04);
  const Eigen::Vector3d direction = Eigen::Vector3d(1.0, 1.0, 0.0).normalized();
  for (const double distance : {0.0, 0.001, 0.01, 0.03})
  {
    const WalkResult walk = walkPrimitive(sphere, top, direction, distance, limitsFor(Eigen::Vector3d::UnitZ()));
    const double phi = distance / 0.04;
    const Eigen::Vector3d exact = 0.04 * (Eigen::Vector3d::UnitZ() * std::cos(phi) + direction * std::sin(phi));
    EXPECT_LT((walk.position - exact).norm(), 1e-15) << distance;
    EXPECT_EQ(walk.stop, WalkStop::kDistanceReached);
    EXPECT_DOUBLE_EQ(walk.walked, distance);
    EXPECT_EQ(walk.location.face, -1);
  }
  // tau_a = 60 degrees: stops where the surface normal is 60 degrees from the contact normal.
  const WalkResult far = walkPrimitive(sphere, top, direction, 1.0, limitsFor(Eigen::Vector3d::UnitZ()));
  EXPECT_EQ(far.stop, WalkStop::kAngleLimit);
  EXPECT_NEAR(far.walked, 0.04 * M_PI / 3.0, 1e-15);
  EXPECT_NEAR(std::acos(far.position.normalized().z()), M_PI / 3.0, 1e-12);
  // The friction cone atan(0.5) (26.6 degrees) comes first.
  const WalkResult cone =
      walkPrimitive(sphere, top, direction, 1.0, limitsFor(Eigen::Vector3d::UnitZ(), M_PI / 3, 0.5));
  EXPECT_EQ(cone.stop, WalkStop::kFrictionLimit);
  EXPECT_NEAR(cone.walked, 0.04 * std::atan(0.5), 1e-15);
  // A contact normal tilted 10 degrees towards the walk: the limit comes 10 degrees later.
  const Eigen::Vector3d tilted =
      Eigen::AngleAxisd(10.0 * M_PI / 180.0, Eigen::Vector3d(-1.0, 1.0, 0.0).normalized()) * Eigen::Vector3d::UnitZ();
  ASSERT_GT(tilted.dot(direction), 0.0);
  const WalkResult early = walkPrimitive(sphere, top, direction, 1.0, limitsFor(tilted));
  EXPECT_NEAR(early.walked, 0.04 * (M_PI / 3.0 + 10.0 * M_PI / 180.0), 1e-12);
}

TEST(PrimitiveWalk, CylinderWalksHelicesOnItsMantleAndLinesOnItsCaps)
{
  const double radius = 0.02;
  const double length = 0.1;
  const PrimitiveSurface cylinder{PrimitiveSurface::Kind::kCylinder, radius, length};
  const Eigen::Vector3d side(radius, 0.0, 0.0);
  const double pitch = 0.3;  // rad from the circumference
  const Eigen::Vector3d direction(0.0, std::cos(pitch), std::sin(pitch));
  const WalkResult helix = walkPrimitive(cylinder, side, direction, 0.015, limitsFor(Eigen::Vector3d::UnitX()));
  const double theta = 0.015 * std::cos(pitch) / radius;
  EXPECT_EQ(helix.stop, WalkStop::kDistanceReached);
  EXPECT_LT(
      (helix.position - Eigen::Vector3d(radius * std::cos(theta), radius * std::sin(theta), 0.015 * std::sin(pitch)))
          .norm(),
      1e-15);
  // Around the circumference the normal turns: tau_a stops it at theta = 60 degrees.
  const WalkResult around =
      walkPrimitive(cylinder, side, Eigen::Vector3d::UnitY(), 1.0, limitsFor(Eigen::Vector3d::UnitX()));
  EXPECT_EQ(around.stop, WalkStop::kAngleLimit);
  EXPECT_NEAR(around.walked, radius * M_PI / 3.0, 1e-15);
  // Along the axis nothing turns until the rim, where the cap is 90 degrees away.
  const WalkResult up =
      walkPrimitive(cylinder, side, Eigen::Vector3d::UnitZ(), 1.0, limitsFor(Eigen::Vector3d::UnitX()));
  EXPECT_EQ(up.stop, WalkStop::kAngleLimit);
  EXPECT_NEAR(up.walked, 0.5 * length, 1e-15);
  EXPECT_NEAR(up.position.z(), 0.5 * length, 1e-15);
  // On a cap, a straight line to the rim.
  const Eigen::Vector3d cap_centre(0.0, 0.0, 0.5 * length);
  const WalkResult flat =
      walkPrimitive(cylinder, cap_centre, Eigen::Vector3d::UnitX(), 0.015, limitsFor(Eigen::Vector3d::UnitZ()));
  EXPECT_LT((flat.position - Eigen::Vector3d(0.015, 0.0, 0.05)).norm(), 1e-15);
  const WalkResult rim =
      walkPrimitive(cylinder, cap_centre, Eigen::Vector3d::UnitX(), 0.05, limitsFor(Eigen::Vector3d::UnitZ()));
  EXPECT_EQ(rim.stop, WalkStop::kAngleLimit);
  EXPECT_NEAR(rim.walked, radius, 1e-15);
  // With tau_a = 180 degrees the walk folds over the rim and goes down the mantle (unfolded):
  // 5 mm past the rim it is 5 mm below the cap, on the same meridian; at 45 degrees to the
  // rim it keeps its components along and across the rim.
  const WalkResult over = walkPrimitive(cylinder, cap_centre, Eigen::Vector3d::UnitX(), radius + 0.005,
                                        limitsFor(Eigen::Vector3d::UnitZ(), M_PI));
  EXPECT_EQ(over.stop, WalkStop::kDistanceReached);
  EXPECT_EQ(over.crossings, 1);
  EXPECT_LT((over.position - Eigen::Vector3d(radius, 0.0, 0.5 * length - 0.005)).norm(), 1e-15);
  const Eigen::Vector3d start(radius - 0.001, 0.0, 0.5 * length);
  const Eigen::Vector3d diagonal = Eigen::Vector3d(1.0, 1.0, 0.0).normalized();
  const WalkResult slanted = walkPrimitive(cylinder, start, diagonal, 0.01, limitsFor(Eigen::Vector3d::UnitZ(), M_PI));
  EXPECT_EQ(slanted.crossings, 1);
  EXPECT_NEAR(slanted.position.head<2>().norm(), radius, 1e-15);
  EXPECT_LT(slanted.position.z(), 0.5 * length);
}

TEST(PrimitiveWalk, TheMeshWalkConvergesToTheExactWalk)
{
  // The same sub-god-objects on an icosphere of 1280, 5120 and 20480 triangles: the mesh walk's
  // error against the exact one falls with the edge length.
  const double radius = 0.04;
  const PrimitiveSurface sphere{PrimitiveSurface::Kind::kSphere, radius, 0.0};
  ContactParams params;
  params.walk = WalkVariant::kUnfold;
  ContactQuery query;
  const Eigen::Vector3d point = Eigen::Vector3d(0.3, -0.2, 1.0).normalized() * radius;
  query.normal = point.normalized();
  query.coupling = -0.01 * query.normal;
  query.location.point = point;
  ContactAreaResult exact;
  computeContactArea(sphere, query, params, &exact);
  ASSERT_TRUE(exact.valid);
  EXPECT_EQ(exact.active, params.sub_god_objects);
  double previous = INFINITY;
  for (const int subdivisions : {3, 4, 5})
  {
    const TriangleMesh mesh = TriangleMesh::build(makeIcosphere(radius, subdivisions));
    const SurfaceLocator locator(mesh);
    ContactQuery on_mesh = query;
    on_mesh.location = locator.closest(point);
    ContactAreaResult walked;
    computeContactArea(mesh, on_mesh, params, &walked);
    double error = 0.0;
    for (int i = 0; i < exact.count; ++i)
    {
      EXPECT_NEAR(std::acos(exact.sub_god_objects[i].position.normalized().dot(query.normal)) * radius,
                  exact.sub_god_objects[i].target_distance, 1e-12);
      error = std::max(error, (walked.sub_god_objects[i].position - exact.sub_god_objects[i].position).norm());
    }
    std::printf("[ icosphere %d ] largest sub-god-object error %.3g m\n", mesh.triangleCount(), error);
    EXPECT_LT(error, previous);
    previous = error;
  }
  EXPECT_LT(previous, 2e-5);
}

TEST(PrimitiveWalk, DegenerateStartsAreDroppedNotWalked)
{
  const PrimitiveSurface sphere{PrimitiveSurface::Kind::kSphere, 0.05, 0.0};
  const PrimitiveSurface cylinder{PrimitiveSurface::Kind::kCylinder, 0.02, 0.1};
  const Eigen::Vector3d top(0.0, 0.0, 0.05);
  // A direction along the normal has no way along the surface.
  const WalkResult along_normal =
      walkPrimitive(sphere, top, Eigen::Vector3d::UnitZ(), 0.01, limitsFor(Eigen::Vector3d::UnitZ()));
  EXPECT_EQ(along_normal.stop, WalkStop::kDropped);
  EXPECT_NEAR(along_normal.position.norm(), 0.05, 1e-15);
  EXPECT_EQ(walkPrimitive(cylinder, Eigen::Vector3d(0.02, 0.0, 0.0), Eigen::Vector3d::UnitX(), 0.01,
                          limitsFor(Eigen::Vector3d::UnitX()))
                .stop,
            WalkStop::kDropped);
  // A contact normal 35 degrees from the axis starts on the cap, which lies outside a friction
  // cone of atan(0.5) = 26.6 degrees: dropped, as on the mantle and on meshes.
  const Eigen::Vector3d tilted(std::sin(35.0 * M_PI / 180.0), 0.0, std::cos(35.0 * M_PI / 180.0));
  EXPECT_EQ(walkPrimitive(cylinder, Eigen::Vector3d(0.0, 0.0, 0.05), Eigen::Vector3d::UnitY(), 0.01,
                          limitsFor(tilted, M_PI / 3.0, 0.5))
                .stop,
            WalkStop::kDropped);
  // A surface touched from inside (normal_sign -1) keeps its limits: 60 degrees.
  ContactParams params;
  params.friction = INFINITY;
  WalkLimits inside = makeWalkLimits(params, -Eigen::Vector3d::UnitZ(), -1.0);
  const WalkResult from_inside = walkPrimitive(sphere, top, Eigen::Vector3d::UnitX(), 1.0, inside);
  EXPECT_EQ(from_inside.stop, WalkStop::kAngleLimit);
  EXPECT_NEAR(from_inside.walked, 0.05 * M_PI / 3.0, 1e-12);
}

TEST(PrimitiveWalk, BadInputIsRefused)
{
  const PrimitiveSurface sphere{PrimitiveSurface::Kind::kSphere, 0.04, 0.0};
  EXPECT_EQ(walkPrimitive(sphere, Eigen::Vector3d(NAN, 0, 0), Eigen::Vector3d::UnitX(), 0.01,
                          limitsFor(Eigen::Vector3d::UnitZ()))
                .stop,
            WalkStop::kInvalidInput);
  ContactQuery query;
  query.location.point = Eigen::Vector3d(0.0, 0.0, 0.04);
  query.normal = Eigen::Vector3d::Zero();
  ContactAreaResult result;
  computeContactArea(sphere, query, ContactParams(), &result);
  EXPECT_FALSE(result.valid);
  EXPECT_EQ(result.count, 0);
}
}  // namespace
}  // namespace god_finger
