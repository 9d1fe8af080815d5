// Algorithm 1 (the sub-god-object walk) on the hard parts of real meshes: creases, many small
// coplanar triangles, curved tessellations against the exact geodesic, borders, non-manifold
// edges, needles, vertices, and runaway walks.
#include "god_finger/contact/surface_walk.h"
#include "god_finger/geometry/mesh_primitives.h"
#include "god_finger/geometry/surface_locator.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

namespace god_finger
{
namespace
{
constexpr double kDegree = M_PI / 180.0;

WalkLimits limitsFor(WalkVariant variant, double max_angle = M_PI,
                     double friction = std::numeric_limits<double>::infinity(),
                     const Eigen::Vector3d& normal = Eigen::Vector3d::UnitZ())
{
  ContactParams params;
  params.walk = variant;
  params.max_angle = max_angle;
  params.friction = friction;
  return makeWalkLimits(params, normal, 1.0);
}

// Two planes meeting along the y axis in a concave crease (a valley): z = 0 for x <= 0 and a
// plane rising at `angle` for x >= 0. Normals point up.
TriangleMesh valley(double angle)
{
  TriangleSoup soup;
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  soup.vertices = {{-1, -1, 0}, {0, -1, 0}, {0, 1, 0}, {-1, 1, 0}, {c, -1, s}, {c, 1, s}};
  soup.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}};
  return TriangleMesh::build(soup);
}

// Issue 18: a start whose barycentric coordinates do not sum to 1 (or lie outside the face) is
// not a point of the mesh: refused as invalid input, not walked from somewhere off the surface.
TEST(SurfaceWalk, AStartWhoseBarycentricsDoNotSumToOneIsRefused)
{
  const TriangleMesh mesh = valley(0.0);
  SurfaceLocation start;
  start.face = 0;
  start.barycentric = Eigen::Vector3d(0.5, 0.5, 0.5);  // sums to 1.5
  const WalkLimits limits = limitsFor(WalkVariant::kUnfold);
  EXPECT_EQ(walkSurface(mesh, start, Eigen::Vector3d::UnitX(), 0.1, limits).stop, WalkStop::kInvalidInput);
  EXPECT_STREQ(walkStopName(WalkStop::kInvalidInput), "invalid_input");
  start.barycentric = Eigen::Vector3d(1.2, -0.1, -0.1);  // sums to 1, outside the face
  EXPECT_EQ(walkSurface(mesh, start, Eigen::Vector3d::UnitX(), 0.1, limits).stop, WalkStop::kInvalidInput);
  // Within the tolerance of a snapped location: walked.
  start.barycentric = Eigen::Vector3d(0.3, 0.3, 0.4 - 2e-7);
  EXPECT_EQ(walkSurface(mesh, start, Eigen::Vector3d::UnitX(), 0.01, limits).stop, WalkStop::kDistanceReached);
}

TEST(SurfaceWalk, ConcaveCreaseUnfoldsAndProjects)
{
  const double angle = 30.0 * kDegree;
  const TriangleMesh mesh = valley(angle);
  const SurfaceLocator locator(mesh);
  const Eigen::Vector3d start(-0.05, 0.0, 0.0);
  const double beta = 25.0 * kDegree;  // direction 25 degrees off the crease normal
  const Eigen::Vector3d direction(std::cos(beta), std::sin(beta), 0.0);
  const double distance = 0.2;
  const double to_crease = 0.05 / std::cos(beta);
  const Eigen::Vector3d crossing(0.0, 0.05 * std::tan(beta), 0.0);
  const Eigen::Vector3d right_normal(-std::sin(angle), 0.0, std::cos(angle));

  // Unfold: the angle to the crease is kept, the path is straight in the unfolded plane.
  WalkResult walk = walkSurface(mesh, locator.closest(start), direction, distance, limitsFor(WalkVariant::kUnfold));
  EXPECT_EQ(walk.stop, WalkStop::kDistanceReached);
  EXPECT_EQ(walk.crossings, 1);
  const Eigen::Vector3d unfolded(std::cos(beta) * std::cos(angle), std::sin(beta), std::cos(beta) * std::sin(angle));
  EXPECT_NEAR((walk.position - (crossing + (distance - to_crease) * unfolded)).norm(), 0.0, 1e-14);

  // Project: the paper's projection of the direction onto the new face.
  walk = walkSurface(mesh, locator.closest(start), direction, distance, limitsFor(WalkVariant::kProject));
  EXPECT_EQ(walk.stop, WalkStop::kDistanceReached);
  const Eigen::Vector3d projected = (direction - direction.dot(right_normal) * right_normal).normalized();
  EXPECT_NEAR((walk.position - (crossing + (distance - to_crease) * projected)).norm(), 0.0, 1e-14);
  EXPECT_GT((projected - unfolded).norm(), 1e-3);  // the two variants really differ here

  // tau_a below the crease angle: stop on the crease; the friction cone likewise.
  walk = walkSurface(mesh, locator.closest(start), direction, distance, limitsFor(WalkVariant::kUnfold, angle - 1e-6));
  EXPECT_EQ(walk.stop, WalkStop::kAngleLimit);
  EXPECT_NEAR((walk.position - crossing).norm(), 0.0, 1e-14);
  EXPECT_NEAR(walk.walked, to_crease, 1e-14);
  walk = walkSurface(mesh, locator.closest(start), direction, distance,
                     limitsFor(WalkVariant::kUnfold, M_PI, std::tan(angle) * 0.99));
  EXPECT_EQ(walk.stop, WalkStop::kFrictionLimit);
  walk = walkSurface(mesh, locator.closest(start), direction, distance,
                     limitsFor(WalkVariant::kUnfold, M_PI, std::tan(angle) * 1.01));
  EXPECT_EQ(walk.stop, WalkStop::kDistanceReached);
}

TEST(SurfaceWalk, ManySmallCoplanarTrianglesEqualOneBigTriangle)
{
  const TriangleMesh fine = TriangleMesh::build(makeGrid(1.0, 40));
  const TriangleMesh coarse = TriangleMesh::build(makeGrid(1.0, 1));
  const SurfaceLocator fine_locator(fine);
  const SurfaceLocator coarse_locator(coarse);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> position(-0.4, 0.4);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI);
  std::uniform_real_distribution<double> length(0.0, 0.5);
  double worst = 0.0;
  int most_crossings = 0;
  for (int trial = 0; trial < 300; ++trial)
  {
    Eigen::Vector3d start(position(random), position(random), 0.0);
    double a = angle(random);
    if (trial < 40)
    {
      // Start on grid vertices and walk along the diagonals and axes: exactly through vertices
      // and along edges.
      start = Eigen::Vector3d(0.05 * (trial % 7 - 3), 0.05 * (trial % 5 - 2), 0.0);
      a = (trial % 8) * M_PI / 4.0;
    }
    const Eigen::Vector3d direction(std::cos(a), std::sin(a), 0.0);
    const double distance = length(random);
    const WalkResult on_fine =
        walkSurface(fine, fine_locator.closest(start), direction, distance, limitsFor(WalkVariant::kUnfold));
    const WalkResult on_coarse =
        walkSurface(coarse, coarse_locator.closest(start), direction, distance, limitsFor(WalkVariant::kUnfold));
    ASSERT_EQ(on_fine.stop, WalkStop::kDistanceReached) << "trial " << trial;
    ASSERT_EQ(on_coarse.stop, WalkStop::kDistanceReached);
    const Eigen::Vector3d exact = start + distance * direction;
    worst = std::max(worst, (on_fine.position - exact).norm());
    worst = std::max(worst, (on_coarse.position - exact).norm());
    most_crossings = std::max(most_crossings, on_fine.crossings);
    const WalkResult projected =
        walkSurface(fine, fine_locator.closest(start), direction, distance, limitsFor(WalkVariant::kProject));
    EXPECT_NEAR((projected.position - exact).norm(), 0.0, 1e-12);
  }
  std::printf("[ grid 40x40 ] worst error %.3g m over up to %d crossings\n", worst, most_crossings);
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(most_crossings, 20);
}

// Exact point at geodesic distance d from p (unit sphere point) towards tangent t.
Eigen::Vector3d greatCircle(const Eigen::Vector3d& p, const Eigen::Vector3d& t, double d, double radius)
{
  return radius * (std::cos(d / radius) * p + std::sin(d / radius) * t);
}

TEST(SurfaceWalk, TessellatedSphereApproachesTheGreatCircle)
{
  const double radius = 1.0;
  const double distance = 0.3;
  std::mt19937_64 random(3);
  std::normal_distribution<double> gaussian;
  double previous_error[2] = {1e9, 1e9};
  for (int subdivisions = 2; subdivisions <= 5; ++subdivisions)
  {
    const TriangleMesh mesh = TriangleMesh::build(makeIcosphere(radius, subdivisions));
    const SurfaceLocator locator(mesh);
    double error[2] = {0.0, 0.0};
    const int trials = 100;
    for (int trial = 0; trial < trials; ++trial)
    {
      const Eigen::Vector3d probe = Eigen::Vector3d(gaussian(random), gaussian(random), gaussian(random)).normalized();
      const SurfaceLocation start = locator.closest(probe);
      const Eigen::Vector3d& n = mesh.normals()[start.face];
      const Eigen::Vector3d direction =
          (Eigen::Vector3d(gaussian(random), gaussian(random), gaussian(random)).cross(n)).normalized();
      // The smooth reference starts at the same point pushed onto the sphere, along the same
      // direction made tangent there.
      const Eigen::Vector3d p0 = start.point.normalized();
      const Eigen::Vector3d t0 = (direction - direction.dot(p0) * p0).normalized();
      const Eigen::Vector3d exact = greatCircle(p0, t0, distance, radius);
      for (int v = 0; v < 2; ++v)
      {
        const WalkVariant variant = v == 0 ? WalkVariant::kProject : WalkVariant::kUnfold;
        const WalkResult walk = walkSurface(mesh, start, direction, distance,
                                            limitsFor(variant, M_PI, std::numeric_limits<double>::infinity(), n));
        EXPECT_EQ(walk.stop, WalkStop::kDistanceReached);
        error[v] += (radius * walk.position.normalized() - exact).norm() / trials;
      }
    }
    const double edge = (mesh.corner(0, 0) - mesh.corner(0, 1)).norm();
    std::printf("[ icosphere %d: %6d triangles, edge %.4f ] mean SGO error / d: project %.4f unfold %.4f\n",
                subdivisions, mesh.triangleCount(), edge, error[0] / distance, error[1] / distance);
    // Unfolding follows the polyhedron's geodesic, which converges to the great circle.
    EXPECT_LT(error[1], previous_error[1]);
    previous_error[0] = error[0];
    previous_error[1] = error[1];
    if (subdivisions == 5)
    {
      EXPECT_LT(error[1] / distance, 0.01);
    }
  }
}

TEST(SurfaceWalk, BoundaryEdgeStopsTheWalkOnTheBorder)
{
  TriangleSoup soup = makeGrid(1.0, 10);
  // Remove the two triangles of the cell [0, 0.2] x [0, 0.2]: a square hole.
  TriangleSoup holed;
  holed.vertices = soup.vertices;
  for (const auto& t : soup.triangles)
  {
    const Eigen::Vector3d centroid = (soup.vertices[t[0]] + soup.vertices[t[1]] + soup.vertices[t[2]]) / 3.0;
    if (!(centroid.x() > 0.0 && centroid.x() < 0.2 && centroid.y() > 0.0 && centroid.y() < 0.2))
    {
      holed.triangles.push_back(t);
    }
  }
  const TriangleMesh mesh = TriangleMesh::build(holed);
  ASSERT_EQ(mesh.health().boundary_edges, 40 + 4);
  const SurfaceLocator locator(mesh);
  const WalkResult walk = walkSurface(mesh, locator.closest(Eigen::Vector3d(-0.3, 0.1, 0.0)), Eigen::Vector3d::UnitX(),
                                      0.5, limitsFor(WalkVariant::kUnfold));
  EXPECT_EQ(walk.stop, WalkStop::kBoundaryEdge);
  EXPECT_NEAR((walk.position - Eigen::Vector3d(0.0, 0.1, 0.0)).norm(), 0.0, 1e-14);
  EXPECT_NEAR(walk.walked, 0.3, 1e-14);
  // The outer border too.
  const WalkResult outward = walkSurface(mesh, locator.closest(Eigen::Vector3d(0.7, -0.5, 0.0)),
                                         Eigen::Vector3d::UnitX(), 2.0, limitsFor(WalkVariant::kUnfold));
  EXPECT_EQ(outward.stop, WalkStop::kBoundaryEdge);
  EXPECT_NEAR((outward.position - Eigen::Vector3d(1.0, -0.5, 0.0)).norm(), 0.0, 1e-14);
}

TEST(SurfaceWalk, NonManifoldEdgeStopsTheWalk)
{
  TriangleSoup soup;
  // A flat square of two triangles, plus a fin standing on its diagonal.
  soup.vertices = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 1}};
  soup.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 2, 4}};
  const TriangleMesh mesh = TriangleMesh::build(soup);
  ASSERT_EQ(mesh.health().non_manifold_edges, 1);
  const SurfaceLocator locator(mesh);
  const WalkResult walk = walkSurface(mesh, locator.closest(Eigen::Vector3d(0.5, -0.5, 0.0)),
                                      Eigen::Vector3d(-1, 1, 0).normalized(), 1.0, limitsFor(WalkVariant::kUnfold));
  EXPECT_EQ(walk.stop, WalkStop::kNonManifoldEdge);
  EXPECT_NEAR((walk.position - Eigen::Vector3d(0.0, 0.0, 0.0)).norm(), 0.0, 1e-14);
}

TEST(SurfaceWalk, NeedleTrianglesAreCrossedExactly)
{
  // A flat square whose middle is a sliver of height 1e-6 over a base of 2 (aspect 1e-6).
  TriangleSoup soup;
  const double h = 1e-6;
  soup.vertices = {{-1, -1, 0}, {1, -1, 0}, {1, 0, 0}, {0, h, 0}, {-1, 0, 0}, {1, 1, 0}, {-1, 1, 0}};
  soup.triangles = {{0, 1, 2}, {0, 2, 4}, {4, 2, 3}, {4, 3, 6}, {3, 2, 5}, {3, 5, 6}};
  const TriangleMesh mesh = TriangleMesh::build(soup);
  ASSERT_EQ(mesh.triangleCount(), 6);
  ASSERT_EQ(mesh.health().degenerate_triangles, 0);
  const SurfaceLocator locator(mesh);
  for (double a = 5.0; a < 360.0; a += 10.0)
  {
    const Eigen::Vector3d start(0.3, -0.1, 0.0);
    const Eigen::Vector3d direction(std::cos(a * kDegree), std::sin(a * kDegree), 0.0);
    const WalkResult walk = walkSurface(mesh, locator.closest(start), direction, 0.5, limitsFor(WalkVariant::kProject));
    ASSERT_TRUE(walk.position.allFinite());
    EXPECT_EQ(walk.stop, WalkStop::kDistanceReached) << a;
    EXPECT_NEAR((walk.position - (start + 0.5 * direction)).norm(), 0.0, 1e-12) << a;
  }
}

TEST(SurfaceWalk, ThroughAHighValenceVertex)
{
  // A flat disc fan of 32 triangles around the origin: straight walks through the centre.
  TriangleSoup soup;
  soup.vertices.push_back(Eigen::Vector3d::Zero());
  const int n = 32;
  for (int i = 0; i < n; ++i)
  {
    soup.vertices.emplace_back(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n), 0.0);
  }
  for (int i = 0; i < n; ++i)
  {
    soup.triangles.push_back({0, 1 + i, 1 + (i + 1) % n});
  }
  const TriangleMesh mesh = TriangleMesh::build(soup);
  ASSERT_EQ(mesh.vertexFacesEnd(0) - mesh.vertexFacesBegin(0), n);
  const SurfaceLocator locator(mesh);
  for (int i = 0; i < 2 * n; ++i)
  {
    const double a = M_PI * i / n;  // half of them exactly along spokes
    const Eigen::Vector3d direction(std::cos(a), std::sin(a), 0.0);
    const Eigen::Vector3d start = -0.3 * direction;
    for (WalkVariant variant : {WalkVariant::kProject, WalkVariant::kUnfold})
    {
      const WalkResult walk = walkSurface(mesh, locator.closest(start), direction, 0.6, limitsFor(variant));
      EXPECT_EQ(walk.stop, WalkStop::kDistanceReached) << i;
      EXPECT_NEAR((walk.position - 0.3 * direction).norm(), 0.0, 1e-12) << i;
    }
  }
}

TEST(SurfaceWalk, ConvexCornerBlocksAGeodesic)
{
  // Walking on a cube face straight at a corner: no face beyond can continue a straight line.
  const TriangleMesh mesh = TriangleMesh::build(makeBox(Eigen::Vector3d(0.5, 0.5, 0.5)));
  const SurfaceLocator locator(mesh);
  const Eigen::Vector3d start(0.0, 0.0, 0.5);
  const Eigen::Vector3d direction = Eigen::Vector3d(1, 1, 0).normalized();
  const WalkResult walk = walkSurface(mesh, locator.closest(start), direction, 2.0, limitsFor(WalkVariant::kUnfold));
  EXPECT_EQ(walk.stop, WalkStop::kVertexBlocked);
  EXPECT_NEAR((walk.position - Eigen::Vector3d(0.5, 0.5, 0.5)).norm(), 0.0, 1e-14);
  EXPECT_NEAR(walk.walked, std::sqrt(0.5), 1e-14);
}

TEST(SurfaceWalk, WalkLongerThanTheObjectTerminates)
{
  // A geodesic round and round a sphere never ends by itself: the crossing cap ends it. The
  // contact normal is off every face normal so that no face is at exactly 180 degrees (which
  // the strict "<" of Algorithm 1 would stop at even with tau_a = pi).
  const TriangleMesh mesh = TriangleMesh::build(makeIcosphere(1.0, 2));
  const SurfaceLocator locator(mesh);
  ContactParams params;
  params.max_angle = M_PI;
  params.friction = std::numeric_limits<double>::infinity();
  params.max_crossings = 1000;
  const Eigen::Vector3d normal = Eigen::Vector3d(0.1, 0.2, 0.97).normalized();
  const WalkLimits limits = makeWalkLimits(params, normal, 1.0);
  const SurfaceLocation start = locator.closest(normal);
  const Eigen::Vector3d direction = mesh.normals()[start.face].cross(Eigen::Vector3d(0.3, 1.0, 0.1)).normalized();
  const WalkResult walk = walkSurface(mesh, start, direction, 1e6, limits);
  EXPECT_EQ(walk.stop, WalkStop::kCrossingCap);
  EXPECT_EQ(walk.crossings, 1000);
  EXPECT_TRUE(walk.position.allFinite());
  EXPECT_LE(walk.position.norm(), 1.0 + 1e-12);
  EXPECT_GT(walk.position.norm(), 0.95);
  EXPECT_GT(walk.walked, 100.0);
}

TEST(SurfaceWalk, OpenSurfaceTouchedFromBehind)
{
  // The grid's normals point up; a finger pressing from below has c_n = -z. The walk compares
  // against the flipped normals and still spreads.
  const TriangleMesh mesh = TriangleMesh::build(makeGrid(1.0, 4));
  const SurfaceLocator locator(mesh);
  ContactParams params;
  const WalkLimits limits = makeWalkLimits(params, -Eigen::Vector3d::UnitZ(), -1.0);
  const WalkResult walk =
      walkSurface(mesh, locator.closest(Eigen::Vector3d(0.1, 0.1, -0.1)), Eigen::Vector3d::UnitY(), 0.5, limits);
  EXPECT_EQ(walk.stop, WalkStop::kDistanceReached);
  EXPECT_NEAR((walk.position - Eigen::Vector3d(0.1, 0.6, 0.0)).norm(), 0.0, 1e-14);
}
}  // namespace
}  // namespace god_finger
