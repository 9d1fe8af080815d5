#include "god_finger/contact/radial_frame.h"

#include "god_finger/contact/contact_params.h"

#include <Eigen/Geometry>
#include <array>
#include <cmath>

namespace god_finger
{
namespace
{
// Below this length the projected previous tangent is too short to trust (the normal turned
// by about 90 degrees in one step): fall back to the normal's own basis.
constexpr double kMinProjectedLength = 1e-3;

// cos and sin of 2 pi i / n for every n_SGO (index n) and i < n, filled before main (no work
// and no allocation in the servo loop): each entry is the std::cos / std::sin radialVector
// computed before, so results are unchanged bit for bit.
struct RadialAngles
{
  static constexpr int kMax = ContactParams::kMaxSubGodObjects;
  std::array<std::array<double, kMax>, kMax + 1> cosine{};
  std::array<std::array<double, kMax>, kMax + 1> sine{};
  RadialAngles()
  {
    for (int n = 1; n <= kMax; ++n)
    {
      for (int i = 0; i < n; ++i)
      {
        const double angle = 2.0 * M_PI * static_cast<double>(i) / static_cast<double>(n);
        cosine[n][i] = std::cos(angle);
        sine[n][i] = std::sin(angle);
      }
    }
  }
};
const RadialAngles kRadialAngles;
}  // namespace

Eigen::Vector3d defaultTangent(const Eigen::Vector3d& normal)
{
  const double sign = std::copysign(1.0, normal.z());
  const double a = -1.0 / (sign + normal.z());
  const double b = normal.x() * normal.y() * a;
  return Eigen::Vector3d(1.0 + sign * normal.x() * normal.x() * a, sign * b, -sign * normal.x());
}

Eigen::Vector3d transportTangent(const Eigen::Vector3d& previous, const Eigen::Vector3d& normal)
{
  const Eigen::Vector3d projected = previous - previous.dot(normal) * normal;
  const double length = projected.norm();
  if (!std::isfinite(length) || length < kMinProjectedLength * previous.norm() || length == 0.0)
  {
    return defaultTangent(normal);
  }
  return projected / length;
}

Eigen::Vector3d radialVector(const Eigen::Vector3d& normal, const Eigen::Vector3d& first_tangent, int i, int n)
{
  if (n >= 1 && n <= RadialAngles::kMax && i >= 0 && i < n)
  {
    return kRadialAngles.cosine[n][i] * first_tangent + kRadialAngles.sine[n][i] * normal.cross(first_tangent);
  }
  const double angle = 2.0 * M_PI * static_cast<double>(i) / static_cast<double>(n);
  return std::cos(angle) * first_tangent + std::sin(angle) * normal.cross(first_tangent);
}
}  // namespace god_finger
