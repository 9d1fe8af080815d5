// A soft body's rest shape: a tetrahedral volume mesh (nodes and linear tetrahedra), checked
// once at load, and its boundary surface.
//
// Units: node coordinates in metres, in the body's own frame.
// Invariants after checkedTetMesh():
//  - every node is finite and used by at least one tetrahedron (unused nodes are dropped, and
//    the tetrahedra renumbered);
//  - every tetrahedron has four distinct nodes in range and positive volume: its signed volume
//    det[n1 - n0, n2 - n0, n3 - n0] / 6 > 0 (a file whose tetrahedra all have the other sign is
//    renumbered; one whose tetrahedra disagree is refused: it folds over itself);
//  - no tetrahedron is degenerate: 6 V / L^3 >= kMinTetQuality, L its longest edge (a regular
//    tetrahedron has 0.71).
// surfaceTriangles() are the faces that belong to one tetrahedron only, wound counter-clockwise
// seen from outside (their normals point out of the body). Not real-time: builds tables.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

namespace god_finger
{
// The smallest 6 V / L^3 a tetrahedron may have (slivers below it make the stiffness matrix
// ill-conditioned by more than 1e9).
constexpr double kMinTetQuality = 1e-6;

struct TetMesh
{
  std::vector<Eigen::Vector3d> nodes;
  std::vector<std::array<int, 4>> tets;
};

// What checkedTetMesh() repaired.
struct TetMeshRepairs
{
  int dropped_nodes = 0;    // used by no tetrahedron
  bool reoriented = false;  // every tetrahedron had negative volume: renumbered
};

// The mesh, checked and repaired as above. Throws InputError naming `source` (the file) and the
// first bad node or tetrahedron by its index in the input.
TetMesh checkedTetMesh(TetMesh mesh, const std::string& source, TetMeshRepairs* repairs = nullptr);

// Signed volume of tetrahedron `tet` of `nodes` (m^3): positive when wound as above.
double signedTetVolume(const std::vector<Eigen::Vector3d>& nodes, const std::array<int, 4>& tet);

// The boundary faces, each wound so that its normal points out of the body, in a deterministic
// order (by tetrahedron, then by the face's opposite corner).
std::vector<std::array<int, 3>> surfaceTriangles(const TetMesh& mesh);
}  // namespace god_finger
