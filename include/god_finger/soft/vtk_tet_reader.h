// Tetrahedral volume meshes from legacy VTK files (.vtk), as PyBullet's deformables, Gmsh
// (`gmsh -format vtk`) and meshio write them ("# vtk DataFile ..." or PyBullet's "#vtk ..."): ASCII, DATASET
// UNSTRUCTURED_GRID, POINTS, then CELLS + CELL_TYPES in the version 2 layout (each cell "k i0 .. ik-1") or the version
// 5 one (OFFSETS and CONNECTIVITY arrays). Tetrahedra (cell type 10) make the volume; vertices, lines, triangles and
// quads (types 1-9, Gmsh's boundary cells) are skipped; any other volume cell is refused. CELLS' size field is not
// trusted (PyBullet's own files get it wrong); a file without cell types (no CELL_TYPES, or Bullet's reduced-deformable
// files' bare "CELL_TYPES 10") is read as Bullet reads it: every cell of 4 nodes a tetrahedron, any other refused.
// Everything after CELL_TYPES (POINT_DATA, CELL_DATA, FIELD) is ignored.
//
// Errors: InputError, one line naming the file, the line and the problem: a BINARY file, a
// missing or unknown section, a bad or missing number, a count over the limits below, a cell
// that names a node out of range; then checkedTetMesh()'s (non-finite node, degenerate or
// inverted tetrahedron). Units: the file's coordinates are metres. Not real-time: reads files.
#pragma once

#include "god_finger/soft/tet_mesh.h"

#include <cstddef>
#include <string>

namespace god_finger
{
// Limits that keep a hostile file from taking the machine's memory.
constexpr std::size_t kMaxVtkFileBytes = std::size_t{256} << 20;
constexpr long long kMaxVtkPoints = 2'000'000;
constexpr long long kMaxVtkCells = 12'000'000;

// The checked mesh of the VTK text `text`; `source` names it in errors.
TetMesh parseVtkTetMesh(const std::string& text, const std::string& source, TetMeshRepairs* repairs = nullptr);

// The checked mesh of the file at `path` (at most kMaxVtkFileBytes).
TetMesh readVtkTetMesh(const std::string& path, TetMeshRepairs* repairs = nullptr);

// The mesh as a version 2 ASCII VTK file (what parseVtkTetMesh reads back exactly: 17 digits).
std::string vtkTetMeshText(const TetMesh& mesh, const std::string& title);
}  // namespace god_finger
