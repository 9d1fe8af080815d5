#include "god_finger/contact/contact_sampling.h"

#include "god_finger/support/input_error.h"
#include "god_finger/contact/radial_frame.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace god_finger
{
RandomContacts::RandomContacts(const TriangleMesh& mesh, const ContactParams& params, std::uint64_t seed)
    : mesh_(&mesh), distance_constant_(params.distance_constant), random_(seed)
{
  double total = 0.0;
  cumulative_area_.reserve(mesh.triangleCount());
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    total += 0.5 * (mesh.corner(t, 1) - mesh.corner(t, 0)).cross(mesh.corner(t, 2) - mesh.corner(t, 0)).norm();
    cumulative_area_.push_back(total);
  }
  if (!(total > 0.0))
  {
    throw InputError("mesh has no area to place contacts on");
  }
}

double RandomContacts::unit()
{
  return static_cast<double>(random_() >> 11) / 9007199254740992.0;
}

ContactQuery RandomContacts::next()
{
  const double pick = unit() * cumulative_area_.back();
  const int face = static_cast<int>(std::min<std::ptrdiff_t>(
      std::upper_bound(cumulative_area_.begin(), cumulative_area_.end(), pick) - cumulative_area_.begin(),
      mesh_->triangleCount() - 1));
  const double r1 = std::sqrt(unit());
  const double r2 = unit();
  ContactQuery query;
  query.location = locationFromBarycentric(*mesh_, face, Eigen::Vector3d(1.0 - r1, r1 * (1.0 - r2), r1 * r2));
  query.normal = mesh_->normals()[face];
  const double compression = 3.0 * distance_constant_ * unit();
  const double tangential = compression * unit();
  const double angle = 2.0 * M_PI * unit();
  const Eigen::Vector3d t1 = defaultTangent(query.normal);
  const Eigen::Vector3d t2 = query.normal.cross(t1);
  query.coupling = -compression * query.normal + tangential * (std::cos(angle) * t1 + std::sin(angle) * t2);
  query.depth = compression;
  return query;
}

std::string contactAreaDefect(const SurfaceLocator& locator, const ContactQuery& query, const ContactAreaResult& area,
                              double tolerance)
{
  if (!std::isfinite(area.radius) || !area.point.allFinite() || !area.normal.allFinite())
  {
    return "non-finite radius, point or normal";
  }
  for (int i = 0; i < area.count; ++i)
  {
    const SubGodObject& sgo = area.sub_god_objects[i];
    const std::string which = "sub-god-object " + std::to_string(i) + ": ";
    if (!sgo.position.allFinite() || !std::isfinite(sgo.walk.walked))
    {
      return which + "non-finite position";
    }
    if (sgo.dropped())
    {
      continue;
    }
    if (locator.closest(sgo.position, 0.0).distance > tolerance)  // no snapping onto features
    {
      return which + "off the mesh";
    }
    if ((sgo.position - query.location.point).norm() > sgo.walk.walked + tolerance)
    {
      return which + "farther than it walked";
    }
    if (sgo.walk.walked > sgo.target_distance * (1.0 + 1e-12) + tolerance)
    {
      return which + "walked beyond its target distance";
    }
  }
  return std::string();
}
}  // namespace god_finger
