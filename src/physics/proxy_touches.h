// One step's proxy-body touches (the deepest point of each proxy-body manifold), before they
// become contact areas, and which of them another touch covers. Internal to physics.
//
// Units: SI, world frame (Bullet's manifold points). Real-time safe: the list is reserved once
// (kMaxTouches) and never grows; touches beyond it are dropped.
#pragma once

#include <btBulletDynamicsCommon.h>

#include <cstddef>
#include <vector>

namespace god_finger::internal
{
struct ProxyTouch
{
  btPersistentManifold* manifold = nullptr;
  int point = 0;  // the touch's point in the manifold
  bool proxy_is_a = false;
  int proxy = 0;
  int body = 0;
};

class ProxyTouches
{
 public:
  static constexpr std::size_t kMaxTouches = 256;
  ProxyTouches()
  {
    touches_.reserve(kMaxTouches);
  }
  void clear()
  {
    touches_.clear();
  }
  // Adds `touch`, unless kMaxTouches are there already.
  void add(const ProxyTouch& touch)
  {
    if (touches_.size() < touches_.capacity())
    {
      touches_.push_back(touch);
    }
  }
  std::size_t size() const
  {
    return touches_.size();
  }
  const ProxyTouch& operator[](std::size_t index) const
  {
    return touches_[index];
  }
  // One finger touching one body in several places: a concave body collides as a compound of
  // hulls (collision_shape.h), and where two hulls meet under the finger each gives a contact at
  // nearly the same point. A touch is covered (and dropped) when another touch of the same
  // finger and body is deeper (or as deep and earlier), lies within `max_radius` (r_max, m), and
  // its normal is within kSameRegionAngle: one pad per touched region, walked on the true
  // surface from the deepest point. Touches of a true concave corner (normals further apart)
  // each keep theirs.
  bool coveredByDeeperTouch(std::size_t index, double max_radius) const;

  // Two touches of one finger on one body whose normals differ by less than this (rad) and
  // whose points are within r_max are one touched region.
  static constexpr double kSameRegionAngle = 20.0 * 3.14159265358979323846 / 180.0;

 private:
  std::vector<ProxyTouch> touches_;
};
}  // namespace god_finger::internal
