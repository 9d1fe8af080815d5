#include "god_finger/physics/scene_description.h"

namespace god_finger
{
BodyDescription boxBody(const std::string& name, const Eigen::Vector3d& size, double mass,
                        const Eigen::Vector3d& centre)
{
  BodyDescription body;
  body.name = name;
  body.is_static = !(mass > 0.0);
  body.mass = body.is_static ? 0.0 : mass;
  body.geometry.kind = GeometryKind::kBox;
  body.geometry.size = size;
  body.pose.translation() = centre;
  if (!body.is_static)
  {
    const Eigen::Vector3d squared = size.cwiseProduct(size);
    body.inertia =
        (mass / 12.0 * Eigen::Vector3d(squared.y() + squared.z(), squared.x() + squared.z(), squared.x() + squared.y()))
            .asDiagonal();
  }
  return body;
}

BodyDescription cylinderBody(const std::string& name, double radius, double length, double mass,
                             const Eigen::Vector3d& centre)
{
  BodyDescription body;
  body.name = name;
  body.is_static = !(mass > 0.0);
  body.mass = body.is_static ? 0.0 : mass;
  body.geometry.kind = GeometryKind::kCylinder;
  body.geometry.radius = radius;
  body.geometry.length = length;
  body.pose.translation() = centre;
  if (!body.is_static)
  {
    const double across = mass * (3.0 * radius * radius + length * length) / 12.0;
    body.inertia = Eigen::Vector3d(across, across, 0.5 * mass * radius * radius).asDiagonal();
  }
  return body;
}
}  // namespace god_finger
