// What the physics layer's Bullet code shares: conversions between Eigen and Bullet (frames
// and units unchanged) and the tags that tell scene bodies from proxies. Internal to physics.
// Real-time safe (no allocation).
#pragma once

#include <btBulletDynamicsCommon.h>

#include <Eigen/Geometry>

namespace god_finger::internal
{
// Collision groups: proxies touch scene bodies, never each other.
constexpr int kBodyGroup = btBroadphaseProxy::DefaultFilter | btBroadphaseProxy::StaticFilter;
constexpr int kProxyGroup = btBroadphaseProxy::CharacterFilter;
// btCollisionObject user index: what an object is; user index 2: its index.
constexpr int kKindBody = 1;
constexpr int kKindProxy = 2;

inline btVector3 toBullet(const Eigen::Vector3d& v)
{
  return btVector3(v.x(), v.y(), v.z());
}

inline Eigen::Vector3d toEigen(const btVector3& v)
{
  return Eigen::Vector3d(v.x(), v.y(), v.z());
}

inline btTransform toBullet(const Eigen::Isometry3d& t)
{
  const Eigen::Matrix3d& r = t.linear();
  return btTransform(btMatrix3x3(r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1), r(1, 2), r(2, 0), r(2, 1), r(2, 2)),
                     toBullet(t.translation()));
}

inline Eigen::Isometry3d toEigen(const btTransform& t)
{
  Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
  const btMatrix3x3& b = t.getBasis();
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      result.linear()(i, j) = b[i][j];
    }
  }
  result.translation() = toEigen(t.getOrigin());
  return result;
}
}  // namespace god_finger::internal
