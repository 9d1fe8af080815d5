// Loads triangle meshes from files: PLY and OFF (by extension, any case) through our own
// readers (ply_reader.h, off_reader.h), STL, OBJ, DAE and whatever else assimp reads through
// assimp. Polygon faces are ear-clipped (polygon_soup.h). All meshes of a file are merged into one soup in the file's
// own coordinates (node transforms applied), triangles in the file's order; `scale` multiplies coordinates (URDF <mesh
// scale>). Units are the file's, taken as metres.
//
// Errors: a missing file, an unreadable or corrupt file, or a file with no triangles throw
// InputError with one line naming the file and the reason. A file too large for the memory
// left (support/memory_budget.h: the counts a PLY, OFF or binary STL header declares, or the size
// of any other file) is refused before it is read, with a ResourceLimitError naming the file,
// the count, the estimate and the limit.
#pragma once

#include "god_finger/geometry/triangle_mesh.h"

#include <string>

namespace god_finger
{
TriangleSoup loadTriangleSoup(const std::string& path, const Eigen::Vector3d& scale = Eigen::Vector3d::Ones());
// loadTriangleSoup + TriangleMesh::build; build errors are reported with the file name.
TriangleMesh loadTriangleMesh(const std::string& path, const Eigen::Vector3d& scale = Eigen::Vector3d::Ones(),
                              const MeshBuildOptions& options = MeshBuildOptions());
}  // namespace god_finger
