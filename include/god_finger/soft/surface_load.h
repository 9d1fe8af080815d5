// Loads on a soft body's surface, as nodal forces: a finger pad's force spread as a uniform
// pressure over the faces it covers (god_finger, soft_finger), and a point force at the closest
// surface point (god_object). A pressure over an area has a finite displacement as the mesh is
// refined; a point force on an elastic body has none (its dimple grows as log(1/h)).
//
// Units: metres and newtons, in the body's frame; nodal forces 3 per node (node i at 3i..3i+2).
// Invariants: the nodal forces added sum to the force given, exactly (to rounding), so momentum
// is what the hand pushes; the pressure is the force over the covered area. RT-safe: allocates
// nothing (the caller owns `forces`).
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

namespace god_finger
{
// A flat circular pad: its centre on the surface, its unit normal pointing out of the body
// (toward the finger), its radius (m).
struct PadDisk
{
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double radius = 0.0;
};

// Sub-triangles per edge of each surface triangle in the pad's quadrature (s^2 points each):
// the covered area's error is O(h / s) along the pad's rim.
constexpr int kPadQuadratureDivisions = 8;

// Adds `force` (N) to `forces` spread as a uniform pressure over the surface under `pad`: the
// points of faces that face the pad (normal . pad normal > 0), lie within `pad.radius` of its
// axis and within `pad.radius` of its plane. Returns the covered area (m^2); 0 (and nothing
// added) when the pad covers no face.
double addPadPressure(const std::vector<Eigen::Vector3d>& positions, const std::vector<std::array<int, 3>>& surface,
                      const PadDisk& pad, const Eigen::Vector3d& force, Eigen::VectorXd* forces);

// Adds `force` at the surface point closest to `point`, split over its face's three nodes by
// barycentric weights. Returns that point.
Eigen::Vector3d addPointForce(const std::vector<Eigen::Vector3d>& positions,
                              const std::vector<std::array<int, 3>>& surface, const Eigen::Vector3d& point,
                              const Eigen::Vector3d& force, Eigen::VectorXd* forces);

// The displacement (m, 3) of the rest surface's point closest to `point`: its face's nodes'
// displacements weighted by its barycentric coordinates (where a dimple's depth is read).
Eigen::Vector3d surfaceDisplacementAt(const std::vector<Eigen::Vector3d>& rest_nodes,
                                      const std::vector<std::array<int, 3>>& surface,
                                      const Eigen::VectorXd& displacement, const Eigen::Vector3d& point);

// Boussinesq's sink (m) of the centre of a uniform pressure `force` / (pi radius^2) over a disk on
// an elastic half-space: w0 = 2 (1 - nu^2) p a / E.
double boussinesqCentreSink(double force, double radius, double young_modulus, double poisson_ratio);
}  // namespace god_finger
