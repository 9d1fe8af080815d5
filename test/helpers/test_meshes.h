// Small meshes with nasty features, shared by the tests.
#pragma once

#include "god_finger/geometry/triangle_mesh.h"

namespace god_finger
{
namespace test
{
// Every soup vertex scaled by `scale` then moved by `offset`.
TriangleSoup transformed(const TriangleSoup& soup, double scale, const Eigen::Vector3d& offset);
// A unit-ish cube as an STL file stores it: every triangle with its own three vertices.
TriangleSoup duplicatedVerticesCube(double half = 0.5);
// The cube with triangles 1, 4 and 7 wound the wrong way.
TriangleSoup inconsistentWindingCube();
// The cube wound inside out (every triangle reversed).
TriangleSoup insideOutCube();
// A Moebius strip of 8 quads: no consistent winding exists.
TriangleSoup moebiusSoup();
// Closed cone whose apex has `n` incident triangles.
TriangleSoup highValenceConeSoup(int n = 32);
}  // namespace test
}  // namespace god_finger
