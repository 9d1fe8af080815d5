#include "solver/pad_geometry.h"

#include <algorithm>

namespace god_finger::internal
{
PadGeometry padGeometry(const Eigen::Vector3d& centre, const Eigen::Vector3d& normal, const WorldContactArea& area)
{
  PadGeometry pad;
  pad.centre_of_pressure = centre;
  const int count = area.sub_god_object_count;
  if (count < 3)
  {
    return pad;
  }
  // The rim in the tangent plane, relative to the contact point: a fan of triangles
  // (centre, rim i, rim i + 1), closed around.
  std::array<Eigen::Vector3d, ContactParams::kMaxSubGodObjects> rim;
  for (int i = 0; i < count; ++i)
  {
    const Eigen::Vector3d offset = area.positions[i] - centre;
    rim[i] = offset - normal * normal.dot(offset);
  }
  // Signed about the normal: consecutive sub-god-objects turn one way around the centre; a
  // triangle that turns back (the closing one, when the kept sub-god-objects span less than a
  // half turn, e.g. at a corner where the others were dropped) would cover the others again.
  auto triangleArea = [&](int i)
  {
    const double signed_area = 0.5 * normal.dot(rim[i].cross(rim[(i + 1) % count]));
    return std::max(0.0, signed_area);
  };
  double area_sum = 0.0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (int i = 0; i < count; ++i)
  {
    const double triangle = triangleArea(i);
    area_sum += triangle;
    moment += triangle * (rim[i] + rim[(i + 1) % count]) / 3.0;
  }
  if (!(area_sum > 0.0))
  {
    return pad;
  }
  const Eigen::Vector3d cop = moment / area_sum;
  pad.centre_of_pressure = centre + cop;
  // Mean of |r - cop| over each triangle: exact for a circular sector about its apex
  // ((2/3) R); the apex's own distance enters with the remaining third.
  double lever_sum = 0.0;
  double rim_sum = 0.0;
  for (int i = 0; i < count; ++i)
  {
    const Eigen::Vector3d& u = rim[i];
    const Eigen::Vector3d& v = rim[(i + 1) % count];
    const double triangle = triangleArea(i);
    const double mean = ((u - cop).norm() + (v - cop).norm()) / 3.0 + cop.norm() / 3.0;
    lever_sum += triangle * mean;
    rim_sum += (u - cop).norm();
  }
  pad.torsional_lever = lever_sum / area_sum;
  pad.support_radius = rim_sum / count;
  return pad;
}
}  // namespace god_finger::internal
