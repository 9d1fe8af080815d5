// A pad's force spread over the faces it covers, and a point force (surface_load.h): the nodal
// forces sum to the force, the pad's centre of pressure is its centre, its area tends to pi a^2
// as the mesh is refined, faces turned away get nothing, a point force's centre is its point.
#include "god_finger/soft/surface_load.h"
#include "god_finger/soft/block_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace god_finger
{
namespace
{
struct Loaded
{
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // about `about`
  double bottom_load = 0.0;                          // |force| on the nodes of the bottom face
};

Loaded sum(const TetMesh& mesh, const Eigen::VectorXd& forces, const Eigen::Vector3d& about)
{
  Loaded loaded;
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
  {
    const Eigen::Vector3d f = forces.segment<3>(3 * n);
    loaded.total += f;
    loaded.moment += (mesh.nodes[n] - about).cross(f);
    if (mesh.nodes[n].z() < 1e-12)
    {
      loaded.bottom_load += f.norm();
    }
  }
  return loaded;
}

TetMesh block(int cells)
{
  BlockMeshSpec spec;
  spec.cells = {cells, cells, cells};
  spec.grading = 3.0;
  return blockTetMesh(spec);
}

TEST(PadPressure, SumsToTheForceCentredOnThePadOverPiASquared)
{
  const Eigen::Vector3d force(0.3, -0.2, -1.5);  // pressing, and dragging sideways
  for (int cells : {5, 9, 17})
  {
    const TetMesh mesh = block(cells);
    const auto surface = surfaceTriangles(mesh);
    PadDisk pad;
    pad.centre = Eigen::Vector3d(0.004, -0.003, 0.1);
    pad.radius = 0.012;
    Eigen::VectorXd forces = Eigen::VectorXd::Zero(3 * mesh.nodes.size());
    const double area = addPadPressure(mesh.nodes, surface, pad, force, &forces);
    const Loaded loaded = sum(mesh, forces, pad.centre);
    EXPECT_LT((loaded.total - force).norm(), 1e-13) << cells << " cells";
    // The centre of pressure (the normal load's moment about the pad's centre over the load) is
    // off the centre by the quadrature's error along the rim only: under 3 % of the radius, 1 %
    // on the finest mesh. (The shear acts in the surface: its moment is about the vertical.)
    const double offset = std::hypot(loaded.moment.x(), loaded.moment.y()) / std::abs(force.z());
    std::printf("%d cells: area / pi a^2 - 1 = %.4f, centre of pressure off by %.3f a\n", cells,
                area / (M_PI * pad.radius * pad.radius) - 1.0, offset / pad.radius);
    EXPECT_LT(offset, (cells == 17 ? 0.01 : 0.03) * pad.radius) << cells << " cells";
    EXPECT_EQ(loaded.bottom_load, 0.0);
    const double error = std::abs(area / (M_PI * pad.radius * pad.radius) - 1.0);
    EXPECT_LT(error, cells == 17 ? 0.01 : 0.04) << cells << " cells";
  }
}

TEST(PadPressure, APadOverNoFaceAddsNothing)
{
  const TetMesh mesh = block(3);
  const auto surface = surfaceTriangles(mesh);
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(3 * mesh.nodes.size());
  PadDisk away;
  away.centre = Eigen::Vector3d(0.0, 0.0, 0.3);  // 20 cm above the top face: more than a radius off its plane
  away.radius = 0.01;
  EXPECT_EQ(addPadPressure(mesh.nodes, surface, away, Eigen::Vector3d(0, 0, -1), &forces), 0.0);
  PadDisk upside_down;
  upside_down.centre = Eigen::Vector3d(0.0, 0.0, 0.1);
  upside_down.normal = -Eigen::Vector3d::UnitZ();  // facing into the body: the top faces face away
  upside_down.radius = 0.01;
  EXPECT_EQ(addPadPressure(mesh.nodes, surface, upside_down, Eigen::Vector3d(0, 0, 1), &forces), 0.0);
  EXPECT_EQ(forces.norm(), 0.0);
}

TEST(PointForce, GoesToTheClosestFacesNodesCentredOnItsPoint)
{
  const TetMesh mesh = block(4);
  const auto surface = surfaceTriangles(mesh);
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(3 * mesh.nodes.size());
  const Eigen::Vector3d force(0.1, 0.0, -2.0);
  const Eigen::Vector3d at = addPointForce(mesh.nodes, surface, Eigen::Vector3d(0.013, 0.021, 0.104), force, &forces);
  EXPECT_LT((at - Eigen::Vector3d(0.013, 0.021, 0.1)).norm(), 1e-15);
  const Loaded loaded = sum(mesh, forces, at);
  EXPECT_LT((loaded.total - force).norm(), 1e-15);
  EXPECT_LT(loaded.moment.norm(), 1e-15);
  int loaded_nodes = 0;
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
  {
    loaded_nodes += forces.segment<3>(3 * n).norm() > 0.0 ? 1 : 0;
  }
  EXPECT_LE(loaded_nodes, 3);
  EXPECT_GE(loaded_nodes, 1);
}
}  // namespace
}  // namespace god_finger
