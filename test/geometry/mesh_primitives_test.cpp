// The generated shapes are closed, outward, of the right topology and on their analytic
// surfaces.
#include "god_finger/geometry/mesh_primitives.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <cmath>

namespace god_finger
{
namespace
{
double volume(const TriangleMesh& mesh)
{
  double v = 0.0;
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    v += mesh.corner(t, 0).dot(mesh.corner(t, 1).cross(mesh.corner(t, 2))) / 6.0;
  }
  return v;
}

int eulerCharacteristic(const TriangleMesh& mesh)
{
  // Closed triangle meshes: E = 3F/2.
  return mesh.vertexCount() - 3 * mesh.triangleCount() / 2 + mesh.triangleCount();
}

void expectClosedAndOutward(const TriangleMesh& mesh, int euler, double expected_volume, double volume_tolerance)
{
  EXPECT_EQ(mesh.health().boundary_edges, 0);
  EXPECT_EQ(mesh.health().non_manifold_edges, 0);
  EXPECT_EQ(mesh.health().flipped_triangles, 0);  // generated right, not repaired
  EXPECT_EQ(mesh.health().welded_vertices, 0);
  EXPECT_EQ(mesh.health().degenerate_triangles, 0);
  EXPECT_EQ(eulerCharacteristic(mesh), euler);
  EXPECT_NEAR(volume(mesh), expected_volume, volume_tolerance);
}

TEST(MeshPrimitives, Box)
{
  const TriangleMesh box = TriangleMesh::build(makeBox(Eigen::Vector3d(0.1, 0.2, 0.3)));
  EXPECT_EQ(box.triangleCount(), 12);
  expectClosedAndOutward(box, 2, 0.2 * 0.4 * 0.6, 1e-15);
}

TEST(MeshPrimitives, IcosphereVerticesLieOnTheSphere)
{
  const double ball = 4.0 / 3.0 * M_PI * std::pow(0.05, 3);
  double previous_deficit = 0.0;
  for (int s = 0; s <= 5; ++s)
  {
    const TriangleMesh sphere = TriangleMesh::build(makeIcosphere(0.05, s));
    EXPECT_EQ(sphere.triangleCount(), 20 * (1 << (2 * s)));
    for (const Eigen::Vector3d& v : sphere.vertices())
    {
      EXPECT_NEAR(v.norm(), 0.05, 1e-12 * 0.05);
    }
    expectClosedAndOutward(sphere, 2, ball, ball);
    // An inscribed polyhedron: its volume approaches the ball's from below, the deficit
    // shrinking about 4 times per subdivision (edges halve; second-order convergence).
    const double deficit = (ball - volume(sphere)) / ball;
    EXPECT_GT(deficit, 0.0);
    if (s >= 2)
    {
      EXPECT_NEAR(deficit / previous_deficit, 0.25, 0.02) << s;
    }
    previous_deficit = deficit;
  }
}

TEST(MeshPrimitives, Cylinder)
{
  const TriangleMesh cylinder = TriangleMesh::build(makeCylinder(0.03, 0.12, 48));
  EXPECT_EQ(cylinder.triangleCount(), 4 * 48);
  const double exact = 0.5 * 48 * std::sin(2 * M_PI / 48) * 0.03 * 0.03 * 0.12;  // inscribed prism
  expectClosedAndOutward(cylinder, 2, exact, 1e-15);
}

TEST(MeshPrimitives, TorusHasGenusOne)
{
  const TriangleMesh torus = TriangleMesh::build(makeTorus(0.06, 0.02, 48, 24));
  const double smooth = 2.0 * M_PI * M_PI * 0.06 * 0.02 * 0.02;
  expectClosedAndOutward(torus, 0, smooth, 0.02 * smooth);
}

TEST(MeshPrimitives, LBlockIsConcave)
{
  const TriangleMesh block = TriangleMesh::build(makeLBlock(0.05, 0.05));
  expectClosedAndOutward(block, 2, 3 * 0.05 * 0.05 * 0.05, 1e-15);
}

TEST(MeshPrimitives, MugIsACupAndARingHandle)
{
  const double r = 0.04, h = 0.09, wall = 0.005, bottom = 0.006;
  const TriangleMesh mug = TriangleMesh::build(makeMug(r, h, wall, bottom, 48));
  // A closed cup (a sphere's topology) and a torus: Euler characteristic 2 + 0; the volumes add.
  const double cup = M_PI * (r * r * h - (r - wall) * (r - wall) * (h - bottom));
  const double handle = 2.0 * M_PI * M_PI * (0.45 * h / 2.0) * wall * wall;
  expectClosedAndOutward(mug, 2, cup + handle, 0.02 * (cup + handle));
  // Standing on z = 0, the handle on +x, no higher than the rim.
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& vertex : mug.vertices())
  {
    box.extend(vertex);
  }
  EXPECT_NEAR(box.min().z(), 0.0, 1e-15);
  EXPECT_NEAR(box.max().z(), h, 1e-15);
  EXPECT_GT(box.max().x(), r + 0.02);
  EXPECT_NEAR(box.min().x(), -r, 1e-15);
  EXPECT_THROW(makeMug(0.04, 0.09, 0.05, 0.006, 48), InputError);
  EXPECT_THROW(makeMug(0.04, 0.09, 0.005, 0.1, 48), InputError);
  EXPECT_THROW(makeMug(0.04, 0.09, 0.005, 0.006, 2), InputError);
}

// The volume a closed (r, z) profile sweeps about z, by Pappus: 2 pi times the profile's area
// times its centroid's r.
double revolvedVolume(const std::vector<Eigen::Vector2d>& profile)
{
  double twice_area = 0.0;
  double six_area_r = 0.0;
  for (std::size_t i = 0; i < profile.size(); ++i)
  {
    const Eigen::Vector2d& p = profile[i];
    const Eigen::Vector2d& q = profile[(i + 1) % profile.size()];
    const double cross = p.x() * q.y() - q.x() * p.y();
    twice_area += cross;
    six_area_r += (p.x() + q.x()) * cross;
  }
  return 2.0 * M_PI * six_area_r / 6.0;
}

TEST(MeshPrimitives, CupAndPlateAreClosedHollowRevolvedShapes)
{
  // 96 segments: the polygon's volume is within 0.1 % of the revolved profile's.
  const TriangleMesh cup = TriangleMesh::build(makeCup(0.04, 0.08, 0.004, 0.012, 96));
  const double cup_volume =
      revolvedVolume({{0, 0}, {0.04, 0}, {0.04, 0.08}, {0.036, 0.08}, {0.036, 0.012}, {0, 0.012}});
  expectClosedAndOutward(cup, 2, cup_volume, 0.002 * cup_volume);
  const TriangleMesh plate = TriangleMesh::build(makePlate(0.1, 0.02, 0.004, 96));
  const double plate_volume =
      revolvedVolume({{0, 0}, {0.06, 0}, {0.1, 0.02}, {0.096, 0.02}, {0.058, 0.004}, {0, 0.004}});
  expectClosedAndOutward(plate, 2, plate_volume, 0.002 * plate_volume);
  // Hollow: the cup holds far less than the cylinder it fills.
  EXPECT_LT(cup_volume, 0.35 * M_PI * 0.04 * 0.04 * 0.08);
  EXPECT_THROW(makeCup(0.04, 0.08, 0.04, 0.012, 32), InputError);
  EXPECT_THROW(makePlate(0.1, 0.02, 0.02, 32), InputError);
  EXPECT_THROW(makePlate(0.1, 0.02, 0.004, 2), InputError);
  EXPECT_THROW(makeRevolved({{0, 0}, {-0.01, 0}, {0, 0.01}}, 8), InputError);
  EXPECT_THROW(makeRevolved({{0, 0}, {0.01, 0}}, 8), InputError);
}

TEST(MeshPrimitives, GridCoversTheSquareExactly)
{
  const TriangleMesh grid = TriangleMesh::build(makeGrid(1.0, 7));
  EXPECT_EQ(grid.triangleCount(), 2 * 49);
  EXPECT_EQ(grid.health().boundary_edges, 28);
  double area = 0.0;
  for (int t = 0; t < grid.triangleCount(); ++t)
  {
    area += 0.5 * (grid.corner(t, 1) - grid.corner(t, 0)).cross(grid.corner(t, 2) - grid.corner(t, 0)).z();
    EXPECT_EQ(grid.normals()[t], Eigen::Vector3d(0, 0, 1));
  }
  EXPECT_NEAR(area, 4.0, 1e-14);
}

TEST(MeshPrimitives, BadArgumentsThrow)
{
  EXPECT_THROW(makeBox(Eigen::Vector3d(0.1, 0.0, 0.1)), InputError);
  EXPECT_THROW(makeIcosphere(-1.0, 2), InputError);
  EXPECT_THROW(makeIcosphere(1.0, 9), InputError);
  EXPECT_THROW(makeCylinder(0.1, 0.1, 2), InputError);
  EXPECT_THROW(makeTorus(0.1, 0.2, 8, 8), InputError);
  EXPECT_THROW(makeGrid(1.0, 0), InputError);
  EXPECT_THROW(makeLBlock(std::nan(""), 1.0), InputError);
}
}  // namespace
}  // namespace god_finger
