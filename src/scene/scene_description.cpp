#include "god_finger/scene/scene_description.h"

namespace god_finger
{
namespace
{
// A body of `geometry` at `centre` (m, world), axis-aligned, static when `mass` (kg) is not
// positive; its inertia is the caller's.
BodyDescription solidBody(const std::string& name, const Geometry& geometry, double mass, const Eigen::Vector3d& centre)
{
  BodyDescription body;
  body.name = name;
  body.is_static = !(mass > 0.0);
  body.mass = body.is_static ? 0.0 : mass;
  body.geometry = geometry;
  body.pose.translation() = centre;
  return body;
}
}  // namespace

BodyDescription boxBody(const std::string& name, const Eigen::Vector3d& size, double mass,
                        const Eigen::Vector3d& centre)
{
  Geometry geometry;
  geometry.kind = GeometryKind::kBox;
  geometry.size = size;
  BodyDescription body = solidBody(name, geometry, mass, centre);
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
  Geometry geometry;
  geometry.kind = GeometryKind::kCylinder;
  geometry.radius = radius;
  geometry.length = length;
  BodyDescription body = solidBody(name, geometry, mass, centre);
  if (!body.is_static)
  {
    const double across = mass * (3.0 * radius * radius + length * length) / 12.0;
    body.inertia = Eigen::Vector3d(across, across, 0.5 * mass * radius * radius).asDiagonal();
  }
  return body;
}
}  // namespace god_finger
