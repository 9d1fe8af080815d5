// The meshes of a scene assimp read, as triangles: what mesh_loader does with every file that is
// not PLY or OFF, apart so that a scene with missing parts (null arrays assimp may leave) can
// be tested without a file that makes them. Not real-time: allocates.
#pragma once

#include "god_finger/geometry/triangle_mesh.h"

#include <Eigen/Core>

struct aiScene;

namespace god_finger
{
// Appends every mesh of `scene`'s node tree (rviz's convention for the root's transformation,
// see mesh_loader.cpp) to `soup`, scaled by `scale`. Throws InputError, one line naming what is
// missing, for a node that refers to a mesh that is not there, a mesh with vertices or faces
// but no array of them, or a node with children but no array of them.
void appendAssimpScene(const aiScene& scene, const Eigen::Vector3d& scale, TriangleSoup* soup);
}  // namespace god_finger
