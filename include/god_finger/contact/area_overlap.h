// The overlap of two fingers' contact areas on one body (paper, Discussion: god-fingers computed
// independently may overlap; pushing both devices apart reduces the overlap).
//
// Two areas overlap only where they share surface: on one side of the body, with normals that
// agree, as when two fingers press side by side or slide onto each other. Pads that face each
// other across a body (a pinch of a card, a phone, a book) never overlap, however thin the body:
// that is what a pinch is.
//
// Each area is a disk: its centre c (m, world, on the surface), its unit normal n (world, out of
// the object), its radius r (m), its pad's reach (m, >= 0: how deep past c, against n, the
// finger's pad is pressed; physics/overlap_push.cpp), and the points the pad really covers (its
// sub-god-objects, m, world, on the surface), which leave the disk's plane where the pad wraps
// over an edge. Two areas overlap
//  - kSameSide: when their normals agree within kOverlapAngle, their centres are closer along the
//    common plane's normal (n_a + n_b) than the two reaches plus kOverlapMargin (one layer of
//    surface: two fingers on one flat face are 0 apart), and their disks, projected on the
//    common plane, intersect: the lens area of the projected disks;
//  - kWrapped: when their normals differ by more than kOverlapAngle but less than 90 degrees (a pad
//    that wraps over an edge onto the face the other presses): only the shared part counts. The
//    share of a's points (its centre and its sub-god-objects, each standing for an equal part of
//    its disk) that lie on b's disk (within kOverlapMargin of b's plane and r_b of b's centre),
//    times a's disk area; or the same of b's points on a's disk, whichever is larger;
//  - never when their normals are 90 degrees or more apart (opposite faces, across any wall).
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
  // The pad's sub-god-objects (m, world): `point_count` of them at `points`; none for a flat disk.
  const Eigen::Vector3d* points = nullptr;
  int point_count = 0;
};

enum class OverlapKind
{
  kNone,      // no overlap (area 0)
  kSameSide,  // normals within kOverlapAngle: the lens of the disks
  kWrapped,   // normals within 90 degrees: the part of one pad that lies on the other's disk
};

struct AreaOverlap
{
  OverlapKind kind = OverlapKind::kNone;
  double area = 0.0;  // m^2 (0 without overlap)
  // Unit, in the common plane (normal n_a + n_b), from a's projected centre to b's: pushing a along
  // -direction and b along +direction separates the areas. When the projected centres coincide
  // (closer than 1e-9 m), a fixed unit vector orthogonal to the plane's normal (Eigen's
  // unitOrthogonal). Zero for kNone.
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
};

// The area (m^2) common to two disks of radii r1, r2 (m, >= 0) whose centres are d (m, >= 0)
// apart: 0 when d >= r1 + r2, the smaller disk when one contains the other, the lens in between.
double lensArea(double r1, double r2, double d);

// The overlap of two areas (see above); non-finite input gives kNone.
AreaOverlap areaOverlap(const AreaDisk& a, const AreaDisk& b);
}  // namespace god_finger
