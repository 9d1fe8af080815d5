#include "overlap_push.h"

#include "god_finger/contact/area_overlap.h"

#include <algorithm>
#include <cmath>

namespace god_finger::internal
{
namespace
{
// The disk of an area, and how deep its pad reaches: the fingertip as a sphere of radius r_max
// (the largest pad), pressed until its section by the surface is the area's disk of radius r, is
// sunk r_max - sqrt(r_max^2 - r^2) (m): 0 for a light touch, r_max at most. Across a 2 mm plate,
// two pads of r = 9.8 mm (8 mm deep each) overlap; across a 3 cm bar no squeeze makes them.
AreaDisk diskOf(const WorldContactArea& area, double max_radius)
{
  AreaDisk disk;
  disk.centre = area.point;
  disk.normal = area.normal;
  disk.radius = area.radius;
  const double r = std::min(area.radius, max_radius);
  disk.reach = max_radius - std::sqrt(std::max(0.0, max_radius * max_radius - r * r));
  disk.points = area.positions.data();
  disk.point_count = area.sub_god_object_count;
  return disk;
}

// Whether finger `finger`'s area `area` holds its body against another finger: some other
// finger's area on the same body presses against it (normals more than 90 degrees apart, so
// the two squeeze the body between them). Such a finger is never pushed: the push could slide it
// out of the grasp.
bool holdsAgainstAnother(const std::vector<Proxy>& proxies, int finger, const WorldContactArea& area)
{
  for (int k = 0; k < static_cast<int>(proxies.size()); ++k)
  {
    if (k == finger)
    {
      continue;
    }
    const InterfaceState& other = proxies[k].state;
    for (int c = 0; c < other.contact_count; ++c)
    {
      if (other.contacts[c].body == area.body && other.contacts[c].normal.dot(area.normal) < 0.0)
      {
        return true;
      }
    }
  }
  return false;
}
}  // namespace

void OverlapPush::resize(int interfaces)
{
  targets_.assign(interfaces, Eigen::Vector3d::Zero());
  pushes_.assign(interfaces, Eigen::Vector3d::Zero());
}

void OverlapPush::update(const WorldParams& params, std::vector<Proxy>* proxies)
{
  const int count = static_cast<int>(proxies->size());
  const double max_radius = params.contact.max_radius;
  for (int i = 0; i < count; ++i)
  {
    InterfaceState& state = (*proxies)[i].state;
    state.overlap_area = 0.0;
    for (int c = 0; c < state.contact_count; ++c)
    {
      state.contacts[c].overlap_area = 0.0;
    }
    targets_[i].setZero();
  }
  // Only god-fingers have areas (the other models' contacts are points).
  const int measured = params.model == ContactModel::kGodFinger ? count : 0;
  for (int i = 0; i < measured; ++i)
  {
    Proxy& a = (*proxies)[i];
    for (int j = i + 1; j < measured; ++j)
    {
      Proxy& b = (*proxies)[j];
      for (int ca = 0; ca < a.state.contact_count; ++ca)
      {
        WorldContactArea& area_a = a.state.contacts[ca];
        for (int cb = 0; cb < b.state.contact_count; ++cb)
        {
          WorldContactArea& area_b = b.state.contacts[cb];
          if (area_a.body != area_b.body)
          {
            continue;
          }
          const AreaOverlap overlap = areaOverlap(diskOf(area_a, max_radius), diskOf(area_b, max_radius));
          if (overlap.area <= 0.0)
          {
            continue;
          }
          area_a.overlap_area += overlap.area;
          area_b.overlap_area += overlap.area;
          a.state.overlap_area += overlap.area;
          b.state.overlap_area += overlap.area;
          const Eigen::Vector3d force = params.overlap.stiffness * overlap.area * overlap.direction;
          if (!holdsAgainstAnother(*proxies, i, area_a))
          {
            targets_[i] -= force;
          }
          if (!holdsAgainstAnother(*proxies, j, area_b))
          {
            targets_[j] += force;
          }
        }
      }
    }
  }
  const double max_step = params.overlap.force_rate * params.time_step;
  for (int i = 0; i < count; ++i)
  {
    Eigen::Vector3d target = targets_[i];
    const double max_force = (*proxies)[i].coupling.max_force;
    if (target.norm() > max_force)
    {
      target *= max_force / target.norm();
    }
    const Eigen::Vector3d change = target - pushes_[i];
    const double length = change.norm();
    pushes_[i] = length > max_step ? Eigen::Vector3d(pushes_[i] + change * (max_step / length)) : target;
    (*proxies)[i].state.overlap_push = pushes_[i];
  }
}
}  // namespace god_finger::internal
