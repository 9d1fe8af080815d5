// The overlap of two fingers' contact areas on one body (paper, Discussion: god-fingers computed
// independently may overlap; pushing both devices apart reduces the overlap).
//
// Each area is a disk: its centre c (m, world), its unit normal n (world, out of the object), its
// radius r (m), and its pad's reach (m, >= 0): how deep past c, against n, the finger's pad is
// pressed (physics/overlap_push.cpp: the depth of a fingertip sphere of radius r_max whose section
// is the disk). Two areas overlap when
//  - they lie on the same side of the body (normals within kOverlapAngle), or face each other
//    across a thin wall (normals opposite within kOverlapAngle): pads that would press into each
//    other around the thin object;
//  - their fingers reach a common layer: the centres are closer along the common plane's normal
//    than the sum of the two reaches plus kOverlapMargin (two fingers on one flat face: 0 apart;
//    across a 2 mm plate: 2 mm apart, less than two pads pressed 1 mm or more deep);
//  - and their disks, projected on the common plane (the mid-plane of the two: normal along
//    n_a + n_b, or n_a - n_b when they face each other, through the mid-point of the centres),
//    intersect. The overlap area is the lens area of the projected disks.
//
// Units: SI. Real-time safe (no allocation, no exceptions).
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace god_finger
{
constexpr double kOverlapAngle = M_PI / 6.0;  // rad: 30 degrees of tolerance on the normals
constexpr double kOverlapMargin = 0.001;      // m: added to the two reaches

struct AreaDisk
{
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();   // m, world
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, world, out of the object
  double radius = 0.0;                                // m, >= 0
  double reach = 0.0;                                 // m, >= 0: the pad's depth past c
};

enum class OverlapKind
{
  kNone,      // no overlap (area 0)
  kSameSide,  // normals within kOverlapAngle
  kFacing,    // normals opposite within kOverlapAngle, across a thin wall
};

struct AreaOverlap
{
  OverlapKind kind = OverlapKind::kNone;
  double area = 0.0;  // m^2: the lens area of the projected disks (0 without overlap)
  // Unit, in the common plane, from a's projected centre to b's: pushing a along -direction and b
  // along +direction separates the disks. When the projected centres coincide (closer than 1e-9 m),
  // a fixed unit vector orthogonal to the plane's normal (Eigen's unitOrthogonal). Zero for kNone.
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
};

// The area (m^2) common to two disks of radii r1, r2 (m, >= 0) whose centres are d (m, >= 0)
// apart: 0 when d >= r1 + r2, the smaller disk when one contains the other, the lens in between.
double lensArea(double r1, double r2, double d);

// The overlap of two areas (see above); non-finite input gives kNone.
AreaOverlap areaOverlap(const AreaDisk& a, const AreaDisk& b);
}  // namespace god_finger
