// Closest-point location: the tree agrees with brute force, features are classified at
// exact vertices and edges, and the tree is balanced (depth grows like log n).
#include "god_finger/geometry/surface_locator.h"
#include "god_finger/geometry/mesh_primitives.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <random>

namespace god_finger
{
namespace
{
TEST(SurfaceLocator, AgreesWithBruteForce)
{
  const TriangleMesh mesh = TriangleMesh::build(makeTorus(0.06, 0.02, 48, 24));
  const SurfaceLocator locator(mesh);
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> coordinate(-0.1, 0.1);
  for (int trial = 0; trial < 500; ++trial)
  {
    const Eigen::Vector3d query(coordinate(random), coordinate(random), 0.5 * coordinate(random));
    const SurfaceLocation found = locator.closest(query);
    double best = std::numeric_limits<double>::infinity();
    for (int face = 0; face < mesh.triangleCount(); ++face)
    {
      best = std::min(best, locateOnFace(mesh, face, query).distance);
    }
    ASSERT_GE(found.face, 0);
    EXPECT_EQ(found.distance, best) << "query " << query.transpose();
    EXPECT_NEAR((found.point - query).norm(), found.distance, 1e-15);
    EXPECT_NEAR(found.barycentric.sum(), 1.0, 1e-15);
    EXPECT_GE(found.barycentric.minCoeff(), 0.0);
  }
}

// A deformed surface (a soft body's, each step): moveVertices keeps the triangles and redoes the
// normals and gradients as a fresh build of the moved soup would, bit for bit; the refitted tree
// agrees with brute force on the moved mesh, and the moved mesh's own fresh tree.
TEST(SurfaceLocator, ARefittedTreeFindsTheMovedSurface)
{
  TriangleMesh mesh = TriangleMesh::build(makeTorus(0.06, 0.02, 48, 24));
  SurfaceLocator locator(mesh);
  std::vector<Eigen::Vector3d> moved = mesh.vertices();
  for (Eigen::Vector3d& v : moved)
  {
    // A dent 1 cm deep around the top of the ring at x = 0.06, and a stretch along y.
    const double dent = 0.01 * std::exp(-((v - Eigen::Vector3d(0.06, 0.0, 0.02)).squaredNorm()) / (0.015 * 0.015));
    v = Eigen::Vector3d(v.x(), 1.3 * v.y(), v.z() - dent);
  }
  mesh.moveVertices(moved);
  locator.refit();
  TriangleSoup soup;
  soup.vertices = moved;
  for (const Eigen::Vector3i& t : mesh.triangles())
  {
    soup.triangles.push_back({t[0], t[1], t[2]});
  }
  const TriangleMesh fresh = TriangleMesh::build(soup);
  ASSERT_EQ(fresh.vertices(), mesh.vertices());  // the same order: nothing welded or dropped
  ASSERT_EQ(fresh.triangles(), mesh.triangles());
  EXPECT_EQ(fresh.normals(), mesh.normals());
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    for (int j = 0; j < 3; ++j)
    {
      ASSERT_EQ(fresh.barycentricGradient(t, j), mesh.barycentricGradient(t, j));
    }
  }
  EXPECT_EQ(fresh.boundingBoxDiagonal(), mesh.boundingBoxDiagonal());
  const SurfaceLocator fresh_locator(fresh);
  std::mt19937_64 random(12);
  std::uniform_real_distribution<double> coordinate(-0.1, 0.1);
  for (int trial = 0; trial < 500; ++trial)
  {
    const Eigen::Vector3d query(coordinate(random), 1.3 * coordinate(random), 0.5 * coordinate(random));
    double best = std::numeric_limits<double>::infinity();
    for (int face = 0; face < mesh.triangleCount(); ++face)
    {
      best = std::min(best, locateOnFace(mesh, face, query).distance);
    }
    ASSERT_EQ(locator.closest(query).distance, best);
    ASSERT_EQ(fresh_locator.closest(query).distance, best);
  }
  // A bad move is refused and changes nothing.
  moved.front().x() = std::nan("");
  EXPECT_THROW(mesh.moveVertices(moved), InputError);
  moved.pop_back();
  EXPECT_THROW(mesh.moveVertices(moved), InputError);
  EXPECT_EQ(fresh.vertices(), mesh.vertices());
}

TEST(SurfaceLocator, ClassifiesVerticesEdgesAndFaces)
{
  const TriangleMesh mesh = TriangleMesh::build(makeBox(Eigen::Vector3d(0.5, 0.5, 0.5)));
  const SurfaceLocator locator(mesh);
  SurfaceLocation location = locator.closest(Eigen::Vector3d(0.7, -0.9, 0.8));
  EXPECT_EQ(location.feature, FeatureKind::kVertex);
  EXPECT_EQ(location.point, Eigen::Vector3d(0.5, -0.5, 0.5));
  EXPECT_EQ(location.barycentric.maxCoeff(), 1.0);
  EXPECT_EQ(mesh.corner(location.face, location.feature_index), Eigen::Vector3d(0.5, -0.5, 0.5));

  location = locator.closest(Eigen::Vector3d(0.9, 0.25, 0.9));
  EXPECT_EQ(location.feature, FeatureKind::kEdge);
  EXPECT_NEAR((location.point - Eigen::Vector3d(0.5, 0.25, 0.5)).norm(), 0.0, 1e-15);
  const int k = location.feature_index;
  EXPECT_EQ(location.barycentric[(k + 2) % 3], 0.0);  // exactly zero opposite the edge

  // Within the tolerance of an edge counts as on it; outside it does not.
  location = locator.closest(Eigen::Vector3d(0.5 - 1e-9, 0.25, 0.9));
  EXPECT_EQ(location.feature, FeatureKind::kEdge);
  location = locator.closest(Eigen::Vector3d(0.5 - 1e-5, 0.25, 0.9));
  EXPECT_EQ(location.feature, FeatureKind::kFace);
  location = locator.closest(Eigen::Vector3d(0.1, 0.3, 0.9));
  EXPECT_EQ(location.feature, FeatureKind::kFace);
  EXPECT_NEAR(location.distance, 0.4, 1e-15);
}

TEST(SurfaceLocator, TreeDepthGrowsLogarithmically)
{
  for (int subdivisions = 1; subdivisions <= 6; ++subdivisions)
  {
    const TriangleMesh mesh = TriangleMesh::build(makeIcosphere(1.0, subdivisions));
    const SurfaceLocator locator(mesh);
    const double n = mesh.triangleCount();
    // Median splits: depth = ceil(log2(n / leaf)) + 1.
    EXPECT_LE(locator.depth(), std::ceil(std::log2(n / SurfaceLocator::kLeafSize)) + 1) << n;
    // The project's budget: mesh, neighbour table and tree together <= 200 bytes/triangle.
    const double per_triangle = static_cast<double>(mesh.memoryBytes() + locator.memoryBytes()) / n;
    std::printf("[ %6.0f triangles ] mesh %.1f + tree %.1f = %.1f bytes/triangle, depth %d\n", n,
                static_cast<double>(mesh.memoryBytes()) / n, static_cast<double>(locator.memoryBytes()) / n,
                per_triangle, locator.depth());
    EXPECT_LE(per_triangle, 200.0);
  }
}

TEST(SurfaceLocator, FarFromTheOrigin)
{
  TriangleSoup soup = makeIcosphere(0.05, 3);
  for (Eigen::Vector3d& v : soup.vertices)
  {
    v += Eigen::Vector3d(1e4, 1e4, -1e4);
  }
  const TriangleMesh mesh = TriangleMesh::build(soup);
  const SurfaceLocator locator(mesh);
  const Eigen::Vector3d query = Eigen::Vector3d(1e4, 1e4, -1e4) + Eigen::Vector3d(0.0, 0.0, 0.08);
  const SurfaceLocation location = locator.closest(query);
  EXPECT_NEAR(location.distance, 0.03, 1e-3);  // the icosphere's pole vertex is at 0.05
  EXPECT_TRUE(location.point.allFinite());
}
}  // namespace
}  // namespace god_finger

namespace god_finger
{
namespace
{
TEST(SurfaceLocator, PointsOnNeedleTrianglesAreFoundOnThem)
{
  // A 33 m x 6 cm needle (the shape test/fuzz/walk_fuzz found): a point on it, anywhere, is at
  // distance ~0 from it. The former region test (Ericson 5.1.5) put such points 0.23 mm off.
  TriangleSoup soup;
  soup.vertices = {Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(0.06, 0.0, 0.0), Eigen::Vector3d(0.02, 32.7, 1.5)};
  soup.triangles = {{0, 1, 2}};
  const TriangleMesh mesh = TriangleMesh::build(soup);
  for (const Eigen::Vector3d& barycentric :
       {Eigen::Vector3d(0.428, 2.31e-14, 0.572), Eigen::Vector3d(0.3, 0.3, 0.4), Eigen::Vector3d(0.01, 0.5, 0.49)})
  {
    const Eigen::Vector3d on =
        barycentric[0] * mesh.corner(0, 0) + barycentric[1] * mesh.corner(0, 1) + barycentric[2] * mesh.corner(0, 2);
    const SurfaceLocation location = locateOnFace(mesh, 0, on);
    EXPECT_LT(location.distance, 1e-12) << barycentric.transpose();
    EXPECT_LT((location.point - on).norm(), 1e-12) << barycentric.transpose();
  }
  // Off the needle, beside its long edge a-c in its plane: the closest point is on that edge.
  const Eigen::Vector3d a = mesh.corner(0, 0);
  const Eigen::Vector3d c = mesh.corner(0, 2);
  const Eigen::Vector3d beside = 0.5 * (a + c) + Eigen::Vector3d(-0.01, 0.0, 0.0);
  const Eigen::Vector3d along = (c - a).normalized();
  const double exact = ((beside - a) - (beside - a).dot(along) * along).norm();
  const SurfaceLocation location = locateOnFace(mesh, 0, beside);
  EXPECT_EQ(location.feature, FeatureKind::kEdge);
  EXPECT_NEAR(location.distance, exact, 1e-12);
}
}  // namespace
}  // namespace god_finger
