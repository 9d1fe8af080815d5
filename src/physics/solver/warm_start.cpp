#include "solver/warm_start.h"

#include "bullet_helpers.h"

#include <cmath>

namespace god_finger::internal
{
void anchorIfSticking(const WarmStart& warm, const btTransform& pad_frame, const btCollisionObject& object,
                      double area_radius, btVector3* on_object, btVector3* on_proxy)
{
  const btVector3 anchored_object = object.getWorldTransform() * toBullet(warm.anchor_on_object);
  const btVector3 anchored_proxy = pad_frame * toBullet(warm.anchor_on_proxy);
  const double bound = 0.999 * warm.friction * warm.normal;
  const bool slipped = std::abs(warm.lateral1) >= bound || std::abs(warm.lateral2) >= bound;
  const bool moved_on = (anchored_object - *on_object).length() > 0.25 * area_radius;
  if (!slipped && !moved_on)
  {
    *on_object = anchored_object;
    *on_proxy = anchored_proxy;
  }
}
}  // namespace god_finger::internal
