// The triangle mesh a body's sub-god-objects walk on, in the body's geometry frame (m).
// Meshes walk on themselves (never on their convex decomposition). Primitives walk on a
// tessellation whose largest edge is at most `max_edge`: a box is exact with 12 triangles; a
// sphere is an icosphere (vertices on the sphere); a cylinder has `ceil(2 pi r / max_edge)`
// segments (at least 16). Tessellations are capped at 81920 triangles.
#pragma once

#include "god_finger/geometry/triangle_mesh.h"
#include "god_finger/scene/scene_description.h"

namespace god_finger
{
TriangleMesh makeWalkMesh(const Geometry& geometry, double max_edge);

// The tessellations' resolutions (20 * 4^s triangles for a sphere, 4 n for a cylinder), so
// that a scene's size can be known before anything is built (scene_budget.h).
int walkSphereSubdivisions(double radius, double max_edge);
int walkCylinderSegments(double radius, double max_edge);
}  // namespace god_finger
