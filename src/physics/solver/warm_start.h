// What a solver point of a contact area (a sub-god-object, or the pad's one point) keeps from
// one step to the next, and how the next step anchors it. Internal to physics.
//
// Units: SI. Frames: each anchor in its own body's frame (the proxy's, the object's centre of
// mass frame); the fresh points and the anchor's world image in the world frame. Real-time safe.
#pragma once

#include <btBulletDynamicsCommon.h>

#include <Eigen/Core>

namespace god_finger::internal
{
// The impulses the solver gave the point (to warm-start the next step) and its friction anchor,
// the material points of the pad and of the object it held when it began to stick (the friction
// rows pull them back together, so that a held object does not creep).
struct WarmStart
{
  long step = -1;  // the step the impulses and the anchor are from
  double normal = 0.0;
  double lateral1 = 0.0;
  double lateral2 = 0.0;
  double friction = 0.0;                                       // the point's combined friction
  Eigen::Vector3d anchor_on_proxy = Eigen::Vector3d::Zero();   // m, in the pad's frame (padFrame, proxy.h)
  Eigen::Vector3d anchor_on_object = Eigen::Vector3d::Zero();  // m, in the object's (centre of mass) frame
};

// Replaces the fresh solver points (m, world) by the anchored material points of `warm` (the
// step before) unless that point slipped (a friction row at its bound: Bullet bounds each
// direction by mu times the normal impulse) or its anchor lies away from the fresh point (the
// area, of radius `area_radius` m, moved on). `pad_frame`: the proxy's frame that anchor_on_proxy
// is in (padFrame, proxy.h: an oriented finger's turns with it).
void anchorIfSticking(const WarmStart& warm, const btTransform& pad_frame, const btCollisionObject& object,
                      double area_radius, btVector3* on_object, btVector3* on_proxy);
}  // namespace god_finger::internal
