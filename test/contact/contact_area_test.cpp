// The god-finger contact area end to end: Eq. 1 and 2, the flat-face circle, edge and vertex
// contacts on a cube, invariance to scale and offset, bad input, no heap allocation.
#include "god_finger/contact/contact_area.h"
#include "allocation_counter.h"
#include "god_finger/geometry/mesh_primitives.h"
#include "god_finger/contact/radial_frame.h"
#include "god_finger/geometry/surface_locator.h"
#include "test_meshes.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>

namespace god_finger
{
namespace
{
constexpr double kDegree = M_PI / 180.0;

TriangleMesh bigFlatTriangle()
{
  TriangleSoup soup;
  soup.vertices = {{-10, -10, 0}, {10, -10, 0}, {0, 10, 0}};
  soup.triangles = {{0, 1, 2}};
  return TriangleMesh::build(soup);
}

TEST(ContactRadius, Equation1Limits)
{
  ContactParams params;
  const Eigen::Vector3d up(0, 0, 1);
  EXPECT_EQ(contactRadius(Eigen::Vector3d::Zero(), up, params), 0.0);
  // Pulling away from the surface (v along +c_n) gives no area, never a negative radius.
  EXPECT_EQ(contactRadius(Eigen::Vector3d(0.2, 0, 0.05), up, params), 0.0);
  EXPECT_FALSE(std::signbit(contactRadius(Eigen::Vector3d(0, 0, 0.05), up, params)));
  // A huge pressing force saturates at r_max exactly.
  EXPECT_EQ(contactRadius(Eigen::Vector3d(0, 0, -1e6), up, params), params.max_radius);
  EXPECT_EQ(contactRadius(Eigen::Vector3d(0, 0, -1e300), up, params), params.max_radius);
  // At a compression of D0' the radius is r_max (1 - 1/e).
  EXPECT_NEAR(contactRadius(Eigen::Vector3d(0.003, 0, -params.distance_constant), up, params),
              params.max_radius * (1.0 - std::exp(-1.0)), 1e-18);
  // Monotonic in the compression (up to 30 D0', where 1 - exp(-s/D0') is still below 1 in doubles).
  double previous = 0.0;
  for (double s = 1e-3 * params.distance_constant; s < 30.0 * params.distance_constant; s *= 1.5)
  {
    const double r = contactRadius(Eigen::Vector3d(0, 0, -s), up, params);
    EXPECT_GT(r, previous);
    EXPECT_LE(r, params.max_radius);
    previous = r;
  }
}

TEST(RadialDistance, Equation2Limits)
{
  ContactParams params;
  params.alpha = 2.0;
  const Eigen::Vector3d radial(1, 0, 0);
  EXPECT_EQ(radialDistance(0.007, Eigen::Vector3d::Zero(), radial, params), 0.007);
  // v along r_i shortens that side by alpha, opposite lengthens it by alpha.
  EXPECT_DOUBLE_EQ(radialDistance(0.007, Eigen::Vector3d(1e-3, 0, 0), radial, params), 0.0035);
  EXPECT_DOUBLE_EQ(radialDistance(0.007, Eigen::Vector3d(-1e-3, 0, 0), radial, params), 0.014);
  // A purely normal push leaves it round.
  EXPECT_DOUBLE_EQ(radialDistance(0.007, Eigen::Vector3d(0, 0, -1e-3), radial, params), 0.007);
  params.alpha = 1.0;
  EXPECT_DOUBLE_EQ(radialDistance(0.007, Eigen::Vector3d(1e-3, 0, 0), radial, params), 0.007);
}

TEST(ContactAreaResult, FlatFaceGivesTheEquation2Ellipse)
{
  const TriangleMesh mesh = bigFlatTriangle();
  ContactParams params;
  params.sub_god_objects = 16;
  ContactQuery query;
  query.location = locateOnFace(mesh, 0, Eigen::Vector3d(0.1, -0.2, 0.0));
  query.normal = Eigen::Vector3d(0, 0, 1);
  query.coupling = Eigen::Vector3d(0.003, -0.001, -0.006);
  query.depth = 0.002;
  ContactAreaResult area;
  computeContactArea(mesh, query, params, &area);
  ASSERT_TRUE(area.valid);
  ASSERT_EQ(area.count, 16);
  EXPECT_EQ(area.active, 16);
  const double expected_radius = params.max_radius * (1.0 - std::exp(-0.006 / params.distance_constant));
  EXPECT_NEAR(area.radius, expected_radius, 1e-15);
  const Eigen::Vector3d v_hat = query.coupling.normalized();
  double shortest = 1e9;
  Eigen::Vector3d shortest_direction = Eigen::Vector3d::Zero();
  for (int i = 0; i < area.count; ++i)
  {
    const SubGodObject& sgo = area.sub_god_objects[i];
    const double d = expected_radius * std::pow(params.alpha, -v_hat.dot(sgo.radial));
    EXPECT_NEAR(sgo.target_distance, d, 1e-12 * d);
    const Eigen::Vector3d offset = sgo.position - query.location.point;
    EXPECT_NEAR(offset.norm(), d, 1e-12 * d) << "sub-god-object " << i;
    EXPECT_NEAR((offset / offset.norm() - sgo.radial).norm(), 0.0, 1e-12);
    EXPECT_EQ(sgo.position.z(), 0.0);
    EXPECT_EQ(sgo.walk.stop, WalkStop::kDistanceReached);
    EXPECT_NEAR(sgo.radial.dot(query.normal), 0.0, 1e-15);
    if (offset.norm() < shortest)
    {
      shortest = offset.norm();
      shortest_direction = offset.normalized();
    }
  }
  // The area is shortest on the side the finger pushes towards (it spreads backwards).
  const Eigen::Vector3d tangential(query.coupling.x(), query.coupling.y(), 0.0);
  EXPECT_GT(shortest_direction.dot(tangential.normalized()), std::cos(2.0 * M_PI / 16.0));
}

TEST(ContactAreaResult, NoPressingForceGivesAPointAndNoNan)
{
  const TriangleMesh mesh = bigFlatTriangle();
  ContactQuery query;
  query.location = locateOnFace(mesh, 0, Eigen::Vector3d(0.0, 0.0, 0.0));
  query.normal = Eigen::Vector3d(0, 0, 1);
  query.coupling = Eigen::Vector3d::Zero();
  ContactAreaResult area;
  computeContactArea(mesh, query, ContactParams(), &area);
  ASSERT_TRUE(area.valid);
  EXPECT_EQ(area.radius, 0.0);
  for (int i = 0; i < area.count; ++i)
  {
    EXPECT_TRUE(area.sub_god_objects[i].position.allFinite());
    EXPECT_EQ((area.sub_god_objects[i].position - query.location.point).norm(), 0.0);
  }
}

TEST(ContactAreaResult, NonFiniteInputIsRejectedWithoutOutput)
{
  const TriangleMesh mesh = bigFlatTriangle();
  ContactQuery query;
  query.location = locateOnFace(mesh, 0, Eigen::Vector3d(0.0, 0.0, 0.0));
  query.normal = Eigen::Vector3d(0, 0, 1);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ContactAreaResult area;
  query.coupling = Eigen::Vector3d(nan, 0, -0.01);
  computeContactArea(mesh, query, ContactParams(), &area);
  EXPECT_FALSE(area.valid);
  EXPECT_EQ(area.count, 0);
  query.coupling = Eigen::Vector3d(0, 0, -0.01);
  query.normal = Eigen::Vector3d(0, 0, std::numeric_limits<double>::infinity());
  computeContactArea(mesh, query, ContactParams(), &area);
  EXPECT_FALSE(area.valid);
  query.normal = Eigen::Vector3d::Zero();
  computeContactArea(mesh, query, ContactParams(), &area);
  EXPECT_FALSE(area.valid);
  query.normal = Eigen::Vector3d(0, 0, 1);
  query.location.face = 7;  // not a face of this mesh
  computeContactArea(mesh, query, ContactParams(), &area);
  EXPECT_FALSE(area.valid);
}

class CubeContact : public ::testing::Test
{
 protected:
  CubeContact() : mesh_(TriangleMesh::build(makeBox(Eigen::Vector3d(0.5, 0.5, 0.5)))), locator_(mesh_) {}
  // True when p lies on the cube's surface (one coordinate at +-0.5, the others inside).
  static bool onCubeSurface(const Eigen::Vector3d& p)
  {
    return std::abs(p.cwiseAbs().maxCoeff() - 0.5) < 1e-12 && p.cwiseAbs().maxCoeff() <= 0.5 + 1e-12;
  }
  TriangleMesh mesh_;
  SurfaceLocator locator_;
};

TEST_F(CubeContact, EdgeContactKeepsFacesWithinTauAAndDropsTheRest)
{
  ContactQuery query;
  query.location = locator_.closest(Eigen::Vector3d(0.5, 0.1, 0.5));
  ASSERT_EQ(query.location.feature, FeatureKind::kEdge);
  query.normal = Eigen::Vector3d(1, 0, 1).normalized();  // both faces at exactly 45 degrees
  query.coupling = -0.01 * query.normal;
  ContactParams params;
  params.friction = std::numeric_limits<double>::infinity();
  params.sub_god_objects = 12;
  ContactAreaResult area;

  params.max_angle = 45.0 * kDegree + 1e-9;
  computeContactArea(mesh_, query, params, &area);
  ASSERT_TRUE(area.valid);
  EXPECT_EQ(area.active, 12);
  int on_top = 0;
  int on_side = 0;
  for (int i = 0; i < area.count; ++i)
  {
    const SubGodObject& sgo = area.sub_god_objects[i];
    EXPECT_TRUE(onCubeSurface(sgo.position)) << sgo.position.transpose();
    // Each walk is a straight segment on one face (the area is far smaller than the face).
    EXPECT_NEAR((sgo.position - query.location.point).norm(), sgo.target_distance, 1e-12);
    on_top += std::abs(sgo.position.z() - 0.5) < 1e-12 && sgo.position.x() < 0.5 - 1e-12;
    on_side += std::abs(sgo.position.x() - 0.5) < 1e-12 && sgo.position.z() < 0.5 - 1e-12;
  }
  // 12 radial vectors: 2 run along the edge, 5 go to each face.
  EXPECT_EQ(on_top, 5);
  EXPECT_EQ(on_side, 5);

  params.max_angle = 45.0 * kDegree - 1e-9;
  computeContactArea(mesh_, query, params, &area);
  ASSERT_TRUE(area.valid);
  EXPECT_EQ(area.active, 0);
  for (int i = 0; i < area.count; ++i)
  {
    EXPECT_EQ(area.sub_god_objects[i].walk.stop, WalkStop::kDropped);
  }
}

TEST_F(CubeContact, WalkOverAnEdgeFollowsTauAJustAboveAndBelowNinetyDegrees)
{
  // A contact on the top face 5 cm from the edge x = 0.5, radial vector towards +x, 15 cm to walk.
  const Eigen::Vector3d start(0.45, 0.0, 0.5);
  SurfaceLocation location = locator_.closest(start);
  ContactParams params;
  params.friction = std::numeric_limits<double>::infinity();
  params.max_angle = 90.0 * kDegree + 1e-9;
  params.walk = WalkVariant::kUnfold;
  WalkLimits limits = makeWalkLimits(params, Eigen::Vector3d::UnitZ(), 1.0);
  WalkResult walk = walkSurface(mesh_, location, Eigen::Vector3d::UnitX(), 0.15, limits);
  EXPECT_EQ(walk.stop, WalkStop::kDistanceReached);
  EXPECT_NEAR((walk.position - Eigen::Vector3d(0.5, 0.0, 0.4)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(walk.walked, 0.15, 1e-15);

  // The paper's projection cannot turn a 90-degree fold: it stops on the edge.
  params.walk = WalkVariant::kProject;
  limits = makeWalkLimits(params, Eigen::Vector3d::UnitZ(), 1.0);
  walk = walkSurface(mesh_, location, Eigen::Vector3d::UnitX(), 0.15, limits);
  EXPECT_EQ(walk.stop, WalkStop::kDirectionLost);
  EXPECT_NEAR((walk.position - Eigen::Vector3d(0.5, 0.0, 0.5)).norm(), 0.0, 1e-12);

  params.walk = WalkVariant::kUnfold;
  params.max_angle = 90.0 * kDegree - 1e-9;
  limits = makeWalkLimits(params, Eigen::Vector3d::UnitZ(), 1.0);
  walk = walkSurface(mesh_, location, Eigen::Vector3d::UnitX(), 0.15, limits);
  EXPECT_EQ(walk.stop, WalkStop::kAngleLimit);
  EXPECT_NEAR((walk.position - Eigen::Vector3d(0.5, 0.0, 0.5)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(walk.walked, 0.05, 1e-15);

  // With a finite friction coefficient the cone (atan(theta) < 90 degrees) stops it first.
  params.max_angle = M_PI;
  params.friction = 5.0;
  limits = makeWalkLimits(params, Eigen::Vector3d::UnitZ(), 1.0);
  walk = walkSurface(mesh_, location, Eigen::Vector3d::UnitX(), 0.15, limits);
  EXPECT_EQ(walk.stop, WalkStop::kFrictionLimit);
}

TEST_F(CubeContact, VertexContactSpreadsOverTheThreeFaces)
{
  ContactQuery query;
  query.location = locator_.closest(Eigen::Vector3d(0.6, 0.6, 0.6));
  ASSERT_EQ(query.location.feature, FeatureKind::kVertex);
  EXPECT_EQ(query.location.point, Eigen::Vector3d(0.5, 0.5, 0.5));
  query.normal = Eigen::Vector3d(1, 1, 1).normalized();  // each face at acos(1/sqrt 3) = 54.7 degrees
  query.coupling = -0.02 * query.normal;
  ContactParams params;
  params.friction = std::numeric_limits<double>::infinity();
  params.sub_god_objects = 9;
  params.max_angle = 60.0 * kDegree;
  ContactAreaResult area;
  computeContactArea(mesh_, query, params, &area);
  ASSERT_TRUE(area.valid);
  EXPECT_EQ(area.active, 9);
  int faces_used[3] = {0, 0, 0};
  for (int i = 0; i < area.count; ++i)
  {
    const SubGodObject& sgo = area.sub_god_objects[i];
    EXPECT_TRUE(onCubeSurface(sgo.position)) << sgo.position.transpose();
    EXPECT_NEAR((sgo.position - query.location.point).norm(), sgo.target_distance, 1e-12);
    for (int axis = 0; axis < 3; ++axis)
    {
      faces_used[axis] += std::abs(sgo.position[axis] - 0.5) < 1e-12;
    }
  }
  EXPECT_GT(faces_used[0], 0);
  EXPECT_GT(faces_used[1], 0);
  EXPECT_GT(faces_used[2], 0);

  params.max_angle = 50.0 * kDegree;
  computeContactArea(mesh_, query, params, &area);
  EXPECT_EQ(area.active, 0);
}

TEST(ContactAreaResult, InvariantUnderScaleAndOffset)
{
  // A contact inside a face of a tessellated sphere (so that the located face, hence the
  // contact normal, is unambiguous), repeated on the same mesh scaled and moved far away.
  const TriangleSoup base = makeIcosphere(0.05, 3);
  const TriangleMesh base_mesh = TriangleMesh::build(base);
  const int face = 100;
  const Eigen::Vector3d probe =
      (base_mesh.corner(face, 0) + 2.0 * base_mesh.corner(face, 1) + 3.0 * base_mesh.corner(face, 2)) / 6.0;
  const Eigen::Vector3d normal = base_mesh.normals()[face];
  const Eigen::Vector3d coupling = Eigen::Vector3d(0.002, 0.001, -0.001) - 0.004 * normal;
  ContactParams params;
  params.sub_god_objects = 12;
  ContactAreaResult reference;
  {
    const SurfaceLocator locator(base_mesh);
    ContactQuery query;
    query.location = locator.closest(probe);
    ASSERT_EQ(query.location.face, face);
    query.normal = normal;
    query.coupling = coupling;
    computeContactArea(base_mesh, query, params, &reference);
    ASSERT_TRUE(reference.valid);
    ASSERT_EQ(reference.active, 12);
  }
  const struct
  {
    double scale;
    Eigen::Vector3d offset;
  } cases[] = {{1.0, Eigen::Vector3d(1e4, -1e4, 1e4)},
               {1e-3, Eigen::Vector3d::Zero()},
               {1e3, Eigen::Vector3d::Zero()},
               {1e-3, Eigen::Vector3d(3.0, 2.0, 1.0)}};
  for (const auto& c : cases)
  {
    const TriangleMesh mesh = TriangleMesh::build(test::transformed(base, c.scale, c.offset));
    const SurfaceLocator locator(mesh);
    ContactParams scaled = params;
    scaled.max_radius *= c.scale;
    scaled.distance_constant *= c.scale;
    ContactQuery query;
    query.location = locator.closest(c.scale * probe + c.offset);
    query.normal = normal;
    query.coupling = c.scale * coupling;
    ContactAreaResult area;
    computeContactArea(mesh, query, scaled, &area);
    ASSERT_TRUE(area.valid);
    EXPECT_EQ(area.active, reference.active);
    EXPECT_NEAR(area.radius, c.scale * reference.radius, 1e-9 * c.scale * reference.radius);
    double worst = 0.0;
    for (int i = 0; i < area.count; ++i)
    {
      const Eigen::Vector3d expected = c.scale * reference.sub_god_objects[i].position + c.offset;
      worst = std::max(worst, (area.sub_god_objects[i].position - expected).norm() / (c.scale * reference.radius));
      EXPECT_EQ(area.sub_god_objects[i].walk.stop, reference.sub_god_objects[i].walk.stop);
    }
    // Relative to the contact radius. Double precision alone limits it: at 1e4 m from the
    // origin a coordinate carries 1e4 * 1.1e-16 = 1.8e-12 m, that is 3e-10 of a 6 mm radius.
    EXPECT_LT(worst, 1e-8) << "scale " << c.scale << " offset " << c.offset.transpose();
    std::printf("[ scale %g offset %g m ] worst SGO error / radius = %.3g\n", c.scale, c.offset.norm(), worst);
  }
}

TEST(ContactAreaResult, SteadyStateDoesNotAllocate)
{
  const TriangleMesh mesh = TriangleMesh::build(makeIcosphere(0.05, 4));
  const SurfaceLocator locator(mesh);
  ContactParams params;
  params.sub_god_objects = 64;
  ContactAreaResult area;
  ContactQuery query;
  const long before = test::allocationCount();
  for (int i = 0; i < 200; ++i)
  {
    const double angle = 0.05 * i;
    const Eigen::Vector3d probe(0.06 * std::cos(angle), 0.06 * std::sin(angle), 0.01 * std::sin(3 * angle));
    query.location = locator.closest(probe);
    query.normal = mesh.normals()[query.location.face];
    query.coupling = Eigen::Vector3d(0.001 * std::sin(angle), 0.0, 0.0) - 0.005 * query.normal;
    query.reference_tangent = area.first_tangent;
    computeContactArea(mesh, query, params, &area);
  }
  const long after = test::allocationCount();
  EXPECT_TRUE(area.valid);
  EXPECT_EQ(after - before, 0);
}

TEST(ContactAreaResult, FirstTangentIsTransportedForContinuity)
{
  const TriangleMesh mesh = bigFlatTriangle();
  ContactQuery query;
  query.location = locateOnFace(mesh, 0, Eigen::Vector3d::Zero());
  query.coupling = Eigen::Vector3d(0, 0, -0.004);
  query.reference_tangent = Eigen::Vector3d(0.6, 0.8, 0.0);
  query.normal = Eigen::Vector3d(0, 0, 1);
  ContactAreaResult area;
  computeContactArea(mesh, query, ContactParams(), &area);
  EXPECT_NEAR((area.first_tangent - Eigen::Vector3d(0.6, 0.8, 0.0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((area.sub_god_objects[0].radial - Eigen::Vector3d(0.6, 0.8, 0.0)).norm(), 0.0, 1e-15);
}
}  // namespace
}  // namespace god_finger
