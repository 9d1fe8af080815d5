#include "proxy_touches.h"

#include <cmath>

namespace god_finger::internal
{
bool ProxyTouches::coveredByDeeperTouch(std::size_t index, double max_radius) const
{
  const ProxyTouch& touch = touches_[index];
  const btManifoldPoint& contact = touch.manifold->getContactPoint(touch.point);
  const btVector3 point = touch.proxy_is_a ? contact.getPositionWorldOnB() : contact.getPositionWorldOnA();
  const btVector3 normal = (touch.proxy_is_a ? 1.0 : -1.0) * contact.m_normalWorldOnB;
  for (std::size_t j = 0; j < touches_.size(); ++j)
  {
    const ProxyTouch& other = touches_[j];
    if (j == index || other.proxy != touch.proxy || other.body != touch.body)
    {
      continue;
    }
    const btManifoldPoint& deeper = other.manifold->getContactPoint(other.point);
    const bool is_deeper =
        deeper.getDistance() < contact.getDistance() || (deeper.getDistance() == contact.getDistance() && j < index);
    const btVector3 other_point = other.proxy_is_a ? deeper.getPositionWorldOnB() : deeper.getPositionWorldOnA();
    const btVector3 other_normal = (other.proxy_is_a ? 1.0 : -1.0) * deeper.m_normalWorldOnB;
    if (is_deeper && (other_point - point).length() <= max_radius &&
        other_normal.dot(normal) >= std::cos(kSameRegionAngle))
    {
      return true;
    }
  }
  return false;
}
}  // namespace god_finger::internal
