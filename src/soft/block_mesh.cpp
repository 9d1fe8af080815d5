#include "god_finger/soft/block_mesh.h"

#include "god_finger/support/input_error.h"

#include <algorithm>
#include <cmath>

namespace god_finger
{
namespace
{
// sinh(g s) / sinh(g): s in [-1, 1] to [-1, 1], its slope g / sinh(g) at 0 (g = 0: s).
double stretched(double s, double grading)
{
  return grading > 0.0 ? std::sinh(grading * s) / std::sinh(grading) : s;
}

double across(double half_size, int index, int cells, double grading)
{
  return half_size * stretched(-1.0 + 2.0 * index / cells, grading);
}

double up(double height, int index, int cells, double grading)
{
  return height * (1.0 - stretched(1.0 - static_cast<double>(index) / cells, grading));
}
}  // namespace

TetMesh blockTetMesh(const BlockMeshSpec& spec)
{
  const int nx = spec.cells[0];
  const int ny = spec.cells[1];
  const int nz = spec.cells[2];
  if (nx < 1 || ny < 1 || nz < 1 || !(spec.grading >= 0.0 && spec.grading <= 10.0) || !(spec.size.minCoeff() > 0.0))
  {
    throw InputError("block mesh: cells must be at least 1, grading in [0, 10], and the size positive");
  }
  const auto node_index = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  TetMesh mesh;
  mesh.nodes.reserve(static_cast<std::size_t>((nx + 1) * (ny + 1) * (nz + 1)));
  for (int k = 0; k <= nz; ++k)
  {
    for (int j = 0; j <= ny; ++j)
    {
      for (int i = 0; i <= nx; ++i)
      {
        mesh.nodes.emplace_back(across(spec.size.x() / 2, i, nx, spec.grading),
                                across(spec.size.y() / 2, j, ny, spec.grading), up(spec.size.z(), k, nz, spec.grading));
      }
    }
  }
  // The six paths from corner (0,0,0) to (1,1,1) along the axes, one per order of the axes.
  constexpr int kOrders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  mesh.tets.reserve(static_cast<std::size_t>(6 * nx * ny * nz));
  for (int k = 0; k < nz; ++k)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        for (const auto& order : kOrders)
        {
          std::array<int, 3> at = {i, j, k};
          std::array<int, 4> tet{};
          tet[0] = node_index(at[0], at[1], at[2]);
          for (int step = 0; step < 3; ++step)
          {
            ++at[order[step]];
            tet[step + 1] = node_index(at[0], at[1], at[2]);
          }
          if (signedTetVolume(mesh.nodes, tet) < 0.0)
          {
            std::swap(tet[1], tet[2]);
          }
          mesh.tets.push_back(tet);
        }
      }
    }
  }
  return checkedTetMesh(std::move(mesh), "block mesh");
}

TetMesh ballTetMesh(double radius, int cells)
{
  if (!(radius > 0.0 && std::isfinite(radius)) || cells < 2)
  {
    throw InputError("ball mesh: the radius must be positive and finite and the cells at least 2");
  }
  BlockMeshSpec cube;
  cube.size = Eigen::Vector3d(2.0, 2.0, 2.0);
  cube.cells = {cells, cells, cells};
  TetMesh mesh = blockTetMesh(cube);
  for (Eigen::Vector3d& node : mesh.nodes)
  {
    const Eigen::Vector3d p(node.x(), node.y(), node.z() - 1.0);
    const Eigen::Vector3d q = p.cwiseAbs2();
    const Eigen::Vector3d on_ball(p.x() * std::sqrt(1.0 - q.y() / 2 - q.z() / 2 + q.y() * q.z() / 3),
                                  p.y() * std::sqrt(1.0 - q.z() / 2 - q.x() / 2 + q.z() * q.x() / 3),
                                  p.z() * std::sqrt(1.0 - q.x() / 2 - q.y() / 2 + q.x() * q.y() / 3));
    node = radius * (on_ball + Eigen::Vector3d::UnitZ());
  }
  for (const std::array<int, 4>& tet : mesh.tets)
  {
    if (!(signedTetVolume(mesh.nodes, tet) > 0.0))
    {
      throw InputError("ball mesh: a tetrahedron turned over under the map (" + std::to_string(cells) + " cells)");
    }
  }
  return checkedTetMesh(std::move(mesh), "ball mesh");
}

int cubeCellsForNodes(int nodes)
{
  return std::max(1, static_cast<int>(std::lround(std::cbrt(static_cast<double>(nodes)))) - 1);
}

std::vector<int> nodesAtHeight(const TetMesh& mesh, double height, double tolerance)
{
  std::vector<int> found;
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
  {
    if (std::abs(mesh.nodes[n].z() - height) <= tolerance)
    {
      found.push_back(static_cast<int>(n));
    }
  }
  return found;
}
}  // namespace god_finger
