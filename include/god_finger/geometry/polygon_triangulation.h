// Triangulating one polygon face of a mesh file (OBJ, OFF, PLY and DAE allow faces of any
// number of corners, convex or not, as CAD and modelling tools write them).
//
// The polygon is projected onto its best-fit plane (Newell's normal, so slightly non-planar
// polygons work) and ear-clipped; repeated consecutive corners are skipped, collinear corners
// are kept (no T-junction is opened with the neighbouring faces) and never become the tip of a
// zero-area triangle. Invariants of a success: every triangle lies inside the polygon, turns the
// polygon's way (no flipped triangle) and the triangles' areas add up to the polygon's.
// Not real-time: it allocates. Units: those of the points.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

namespace god_finger
{
// `corners` in order around the polygon. On success fills `triangles` with index triples into
// `corners` and returns ""; a polygon of no area gives no triangle and "". Otherwise (a
// self-intersecting polygon) returns one line saying so and leaves `triangles` empty.
std::string triangulatePolygon(const std::vector<Eigen::Vector3d>& corners, std::vector<std::array<int, 3>>* triangles);
}  // namespace god_finger
