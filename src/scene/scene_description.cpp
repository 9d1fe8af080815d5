#include "god_finger/scene/scene_description.h"

#include "god_finger/support/input_error.h"

#include <cmath>
#include <vector>

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
void checkJoints(const SceneDescription& scene)
{
  const int bodies = static_cast<int>(scene.bodies.size());
  std::vector<int> parent_joint(scene.bodies.size(), -1);
  for (std::size_t j = 0; j < scene.joints.size(); ++j)
  {
    const JointDescription& joint = scene.joints[j];
    const std::string where = "joint '" + joint.name + "': ";
    if (joint.child < 0 || joint.child >= bodies || joint.parent < -1 || joint.parent >= bodies)
    {
      throw InputError(where + "its parent or child is no body of the scene");
    }
    const std::string& child = scene.bodies[joint.child].name;
    if (scene.bodies[joint.child].is_static)
    {
      throw InputError(where + "its child '" + child + "' is fixed: a joint moves a free body");
    }
    if (joint.parent == joint.child)
    {
      throw InputError(where + "'" + child + "' cannot be its own parent");
    }
    if (parent_joint[joint.child] >= 0)
    {
      throw InputError(where + "'" + child + "' is already the child of joint '" +
                       scene.joints[parent_joint[joint.child]].name + "'");
    }
    parent_joint[joint.child] = static_cast<int>(j);
    if (!joint.axis.allFinite() || std::abs(joint.axis.norm() - 1.0) > 1e-6)
    {
      throw InputError(where + "its axis must be a unit vector");
    }
    if (!joint.joint_in_parent.matrix().allFinite() || !std::isfinite(joint.lower) || !std::isfinite(joint.upper) ||
        joint.lower > joint.upper)
    {
      throw InputError(where + "needs a finite frame and finite limits, lower <= upper");
    }
    if (!(joint.damping >= 0.0) || !(joint.friction >= 0.0) || !std::isfinite(joint.damping) ||
        !std::isfinite(joint.friction))
    {
      throw InputError(where + "damping and friction must be finite and >= 0");
    }
  }
}
const char* jointKindName(JointKind kind)
{
  switch (kind)
  {
    case JointKind::kRevolute:
      return "revolute";
    case JointKind::kContinuous:
      return "continuous";
    case JointKind::kPrismatic:
      return "prismatic";
  }
  return "?";
}
}  // namespace god_finger
