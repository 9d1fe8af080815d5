// Tetrahedral meshes of a block, for the soft scenes, the fidelity study and the benchmarks: a
// grid of cells, each split into 6 tetrahedra around its main diagonal (conforming across
// cells), with the grid lines graded toward the top face's centre, where a finger presses.
//
// Units: metres. The block spans x, y in [-size/2, size/2] and z in [0, size.z]: its bottom face
// rests on z = 0. Grading g in [0, 10]: a grid line at uniform parameter s in [-1, 1] sits at
// size/2 * sinh(g s) / sinh(g) across and, for t in [0, 1], at z = size.z (1 - sinh(g (1 - t)) /
// sinh(g)) up (g = 0: uniform); the cells at the top centre are g / sinh(g) of the uniform size,
// those at the far edges g / tanh(g).
#pragma once

#include "god_finger/soft/tet_mesh.h"

#include <Eigen/Core>
#include <array>
#include <vector>

namespace god_finger
{
struct BlockMeshSpec
{
  Eigen::Vector3d size = Eigen::Vector3d(0.1, 0.1, 0.1);
  std::array<int, 3> cells = {9, 9, 9};
  double grading = 0.0;
};

// The block's checked mesh: (cx + 1)(cy + 1)(cz + 1) nodes, 6 cx cy cz tetrahedra.
TetMesh blockTetMesh(const BlockMeshSpec& spec);

// A ball of `radius` (m) made of a cube of `cells` per side (uniform) mapped onto it smoothly
// (x' = x sqrt(1 - y^2/2 - z^2/2 + y^2 z^2 / 3) and its turns, which takes the cube's faces to the
// sphere), centred on x = y = 0 with its lowest point at z = 0: (cells + 1)^3 nodes, 6 cells^3
// tetrahedra. InputError when radius <= 0 or cells < 2 (every tetrahedron keeps its orientation
// under the map for cells >= 2: checked).
TetMesh ballTetMesh(double radius, int cells);

// The cells per side of a cube with about `nodes` nodes: round(cbrt(nodes)) - 1.
int cubeCellsForNodes(int nodes);

// The nodes within `tolerance` (m) of the plane z = height.
std::vector<int> nodesAtHeight(const TetMesh& mesh, double height, double tolerance);
}  // namespace god_finger
