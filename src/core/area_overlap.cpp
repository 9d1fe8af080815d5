#include "god_finger/core/area_overlap.h"

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

AreaOverlap areaOverlap(const AreaDisk& a, const AreaDisk& b)
{
  AreaOverlap result;
  const bool finite = a.centre.allFinite() && b.centre.allFinite() && a.normal.allFinite() && b.normal.allFinite() &&
                      std::isfinite(a.radius) && std::isfinite(b.radius) && std::isfinite(a.reach) &&
                      std::isfinite(b.reach);
  if (!finite || a.radius <= 0.0 || b.radius <= 0.0)
  {
    return result;
  }
  const double cosine = a.normal.dot(b.normal);
  const double tolerance = std::cos(kOverlapAngle);
  Eigen::Vector3d plane_normal;
  OverlapKind kind;
  if (cosine >= tolerance)
  {
    kind = OverlapKind::kSameSide;
    plane_normal = (a.normal + b.normal).normalized();
  }
  else if (cosine <= -tolerance)
  {
    kind = OverlapKind::kFacing;
    plane_normal = (a.normal - b.normal).normalized();
  }
  else
  {
    return result;
  }
  const Eigen::Vector3d between = b.centre - a.centre;
  const double apart = std::abs(between.dot(plane_normal));
  if (!(apart < std::max(0.0, a.reach) + std::max(0.0, b.reach) + kOverlapMargin))
  {
    return result;
  }
  const Eigen::Vector3d in_plane = between - between.dot(plane_normal) * plane_normal;
  const double distance = in_plane.norm();
  const double area = lensArea(a.radius, b.radius, distance);
  if (area <= 0.0)
  {
    return result;
  }
  result.kind = kind;
  result.area = area;
  result.direction = distance > kCoincident ? Eigen::Vector3d(in_plane / distance) : plane_normal.unitOrthogonal();
  return result;
}
}  // namespace god_finger
