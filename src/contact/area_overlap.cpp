#include "god_finger/contact/area_overlap.h"

#include <Eigen/Geometry>
#include <algorithm>

namespace god_finger
{
namespace
{
double clampedAcos(double x)
{
  return std::acos(std::min(1.0, std::max(-1.0, x)));
}

// Projected centres closer than this (m) coincide: the direction between them is arbitrary.
constexpr double kCoincident = 1e-9;
}  // namespace

double lensArea(double r1, double r2, double d)
{
  if (!(d < r1 + r2))
  {
    return 0.0;
  }
  const double small = std::min(r1, r2);
  if (d <= std::abs(r1 - r2))
  {
    return M_PI * small * small;
  }
  const double a1 = r1 * r1 * clampedAcos((d * d + r1 * r1 - r2 * r2) / (2.0 * d * r1));
  const double a2 = r2 * r2 * clampedAcos((d * d + r2 * r2 - r1 * r1) / (2.0 * d * r2));
  const double k = (-d + r1 + r2) * (d + r1 - r2) * (d - r1 + r2) * (d + r1 + r2);
  return a1 + a2 - 0.5 * std::sqrt(std::max(0.0, k));
}

namespace
{
bool finiteDisk(const AreaDisk& disk)
{
  if (!disk.centre.allFinite() || !disk.normal.allFinite() || !std::isfinite(disk.radius) ||
      !std::isfinite(disk.reach) || disk.point_count < 0 || (disk.point_count > 0 && disk.points == nullptr))
  {
    return false;
  }
  for (int i = 0; i < disk.point_count; ++i)
  {
    if (!disk.points[i].allFinite())
    {
      return false;
    }
  }
  return true;
}

// Whether `point` (m, world, on the surface) lies on `disk`: within kOverlapMargin of its plane
// and its radius of its centre.
bool onDisk(const Eigen::Vector3d& point, const AreaDisk& disk)
{
  const Eigen::Vector3d offset = point - disk.centre;
  const double height = offset.dot(disk.normal);
  return std::abs(height) < kOverlapMargin && (offset - height * disk.normal).norm() <= disk.radius;
}

// The part of `pad`'s disk area (m^2) whose points (its centre and its sub-god-objects, an equal
// share each) lie on `other`'s disk.
double sharedPart(const AreaDisk& pad, const AreaDisk& other)
{
  int on = onDisk(pad.centre, other) ? 1 : 0;
  for (int i = 0; i < pad.point_count; ++i)
  {
    on += onDisk(pad.points[i], other) ? 1 : 0;
  }
  return M_PI * pad.radius * pad.radius * on / (pad.point_count + 1);
}

// Unit, in the plane of normal `plane_normal`, from a's centre to b's (see AreaOverlap::direction).
Eigen::Vector3d separation(const AreaDisk& a, const AreaDisk& b, const Eigen::Vector3d& plane_normal)
{
  const Eigen::Vector3d between = b.centre - a.centre;
  const Eigen::Vector3d in_plane = between - between.dot(plane_normal) * plane_normal;
  const double distance = in_plane.norm();
  return distance > kCoincident ? Eigen::Vector3d(in_plane / distance) : plane_normal.unitOrthogonal();
}
}  // namespace

AreaOverlap areaOverlap(const AreaDisk& a, const AreaDisk& b)
{
  AreaOverlap result;
  if (!finiteDisk(a) || !finiteDisk(b) || a.radius <= 0.0 || b.radius <= 0.0)
  {
    return result;
  }
  const double cosine = a.normal.dot(b.normal);
  if (!(cosine > 0.0))
  {
    return result;  // opposite faces: a pinch, never an overlap
  }
  const Eigen::Vector3d plane_normal = (a.normal + b.normal).normalized();
  if (cosine >= std::cos(kOverlapAngle))
  {
    const Eigen::Vector3d between = b.centre - a.centre;
    const double apart = std::abs(between.dot(plane_normal));
    if (!(apart < std::max(0.0, a.reach) + std::max(0.0, b.reach) + kOverlapMargin))
    {
      return result;
    }
    const double area = lensArea(a.radius, b.radius, (between - between.dot(plane_normal) * plane_normal).norm());
    if (area <= 0.0)
    {
      return result;
    }
    result.kind = OverlapKind::kSameSide;
    result.area = area;
  }
  else
  {
    const double area = std::max(sharedPart(a, b), sharedPart(b, a));
    if (area <= 0.0)
    {
      return result;
    }
    result.kind = OverlapKind::kWrapped;
    result.area = area;
  }
  result.direction = separation(a, b, plane_normal);
  return result;
}
}  // namespace god_finger
