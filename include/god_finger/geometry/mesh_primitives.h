// Triangle soups of simple shapes, in metres, centred on the origin unless stated. Used as
// walk meshes for primitives, as shipped meshes and as test fixtures. All are wound
// counter-clockwise seen from outside.
#pragma once

#include "god_finger/geometry/triangle_mesh.h"

#include <Eigen/Core>
#include <vector>

namespace god_finger
{
// Axis-aligned box with the given half extents; each face split into 2 triangles.
TriangleSoup makeBox(const Eigen::Vector3d& half_extents);
// Sphere: an icosahedron subdivided `subdivisions` times, vertices pushed onto the sphere.
TriangleSoup makeIcosphere(double radius, int subdivisions);
// Cylinder along z, capped, `segments` around; caps are fans around a centre vertex.
TriangleSoup makeCylinder(double radius, double length, int segments);
// Square grid in the z = 0 plane, [-half, half]^2, n x n cells each split along the diagonal
// from (x0,y0) to (x1,y1); normal +z.
TriangleSoup makeGrid(double half_size, int cells);
// Torus around z (concave): major radius R, minor radius r.
TriangleSoup makeTorus(double major_radius, double minor_radius, int major_segments, int minor_segments);
// Closed L-shaped block (concave along one edge), extruded along y over [-depth/2, depth/2]:
// the union of [0,2a]x[0,a] and [0,a]x[0,2a] in the x-z plane, with a = arm.
TriangleSoup makeLBlock(double arm, double depth);
// A closed profile in the (r, z) half-plane, counter-clockwise (the section on its left), revolved
// about z in `segments`: a point at r = 0 is one vertex on the axis. Throws InputError for fewer
// than 3 segments or points, a negative r or a non-finite point.
TriangleSoup makeRevolved(const std::vector<Eigen::Vector2d>& profile, int segments);
// Cup standing on z = 0, axis z, open at the top (hollow: its inner floor at z = `bottom`):
// outer radius `radius`, height `height`, wall `wall`, bottom `bottom` thick.
TriangleSoup makeCup(double radius, double height, double wall, double bottom, int segments);
// Plate standing on z = 0, axis z: a flat floor out to 0.6 `radius` (its top at z =
// `thickness`), then a rim sloping up to `radius` at z = `height`; `thickness` thick throughout.
TriangleSoup makePlate(double radius, double height, double thickness, int segments);
// Mug standing on z = 0, axis z: a cup (outer radius `radius`, height `height`, wall `wall`,
// bottom `bottom` thick, open at the top; a closed profile revolved in `segments`) and a ring
// handle on +x (a torus of major radius 0.45 height / 2 and minor radius wall, in the x-z plane,
// its inner edge on the cup's inner wall at half height): two closed components that overlap in
// the wall (concave; collision decomposes it, the walk runs on each component).
TriangleSoup makeMug(double radius, double height, double wall, double bottom, int segments);
}  // namespace god_finger
