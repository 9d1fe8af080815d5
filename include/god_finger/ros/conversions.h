// Eigen vectors and quaternions to geometry_msgs (SI units, frames unchanged).
#pragma once

#include <geometry_msgs/Point.h>
#include <geometry_msgs/Quaternion.h>
#include <geometry_msgs/Vector3.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace god_finger
{
inline geometry_msgs::Point toPoint(const Eigen::Vector3d& p)
{
  geometry_msgs::Point result;
  result.x = p.x();
  result.y = p.y();
  result.z = p.z();
  return result;
}

inline geometry_msgs::Vector3 toVector(const Eigen::Vector3d& v)
{
  geometry_msgs::Vector3 result;
  result.x = v.x();
  result.y = v.y();
  result.z = v.z();
  return result;
}

inline geometry_msgs::Quaternion toQuaternion(const Eigen::Quaterniond& q)
{
  geometry_msgs::Quaternion result;
  result.x = q.x();
  result.y = q.y();
  result.z = q.z();
  result.w = q.w();
  return result;
}

inline Eigen::Vector3d fromVector(const geometry_msgs::Vector3& v)
{
  return Eigen::Vector3d(v.x, v.y, v.z);
}

inline Eigen::Vector3d fromPoint(const geometry_msgs::Point& p)
{
  return Eigen::Vector3d(p.x, p.y, p.z);
}
}  // namespace god_finger
