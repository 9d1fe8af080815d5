#include "god_finger/physics/joint_measure.h"

#include <Eigen/Geometry>
#include <cmath>

namespace god_finger
{
JointState measureJoint(const JointDescription& joint, const BodyState* parent, const BodyState& child)
{
  const Eigen::Isometry3d parent_pose = parent != nullptr ? parent->pose : Eigen::Isometry3d::Identity();
  const Eigen::Isometry3d joint_at_zero = parent_pose * joint.joint_in_parent;  // world
  const Eigen::Isometry3d moved = joint_at_zero.inverse() * child.pose;         // the child in the joint frame
  const Eigen::Vector3d axis_world = joint_at_zero.linear() * joint.axis;
  JointState state;
  if (joint.kind == JointKind::kPrismatic)
  {
    state.position = moved.translation().dot(joint.axis);
    // The child's centre of mass relative to the parent's point under it (a turning parent
    // carries that point along).
    const Eigen::Vector3d parent_velocity =
        parent != nullptr
            ? Eigen::Vector3d(parent->linear_velocity +
                              parent->angular_velocity.cross(child.center_of_mass - parent->center_of_mass))
            : Eigen::Vector3d::Zero();
    state.velocity = (child.linear_velocity - parent_velocity).dot(axis_world);
    return state;
  }
  // The twist about the axis (swing-twist): the rotation's quaternion projected on the axis.
  Eigen::Quaterniond rotation(moved.linear());
  if (rotation.w() < 0.0)
  {
    rotation.coeffs() = -rotation.coeffs();
  }
  state.position = 2.0 * std::atan2(rotation.vec().dot(joint.axis), rotation.w());
  const Eigen::Vector3d parent_spin = parent != nullptr ? parent->angular_velocity : Eigen::Vector3d::Zero();
  state.velocity = (child.angular_velocity - parent_spin).dot(axis_world);
  return state;
}
}  // namespace god_finger
