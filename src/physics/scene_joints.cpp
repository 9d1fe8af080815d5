#include "scene_joints.h"

#include "bullet_helpers.h"

#include <Eigen/Geometry>
#include <cmath>

namespace god_finger::internal
{
namespace
{
// The joint frame turned so that `along` (z for Bullet's hinge, x for its slider) is the
// joint's axis.
Eigen::Isometry3d axisFrame(const Eigen::Vector3d& axis, const Eigen::Vector3d& along)
{
  Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
  frame.linear() = Eigen::Quaterniond::FromTwoVectors(along, axis).toRotationMatrix();
  return frame;
}
}  // namespace

std::unique_ptr<btTypedConstraint> makeJointConstraint(const JointDescription& joint, const SceneBody* parent,
                                                       const SceneBody& child, btRigidBody* world_anchor)
{
  const bool prismatic = joint.kind == JointKind::kPrismatic;
  const Eigen::Isometry3d along =
      axisFrame(joint.axis, prismatic ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitZ());
  // The joint frame in each body's Bullet frame (the world's fixed body sits at the origin).
  const Eigen::Isometry3d in_parent =
      (parent != nullptr ? parent->com_in_link.inverse() : Eigen::Isometry3d::Identity()) * joint.joint_in_parent *
      along;
  const Eigen::Isometry3d in_child = child.com_in_link.inverse() * along;
  btRigidBody& a = parent != nullptr ? *parent->rigid : *world_anchor;
  btRigidBody& b = *child.rigid;
  if (prismatic)
  {
    auto slider = std::make_unique<btSliderConstraint>(a, b, toBullet(in_parent), toBullet(in_child), true);
    slider->setLowerLinLimit(joint.lower);
    slider->setUpperLinLimit(joint.upper);
    slider->setLowerAngLimit(0.0);
    slider->setUpperAngLimit(0.0);
    slider->setPoweredLinMotor(true);
    slider->setTargetLinMotorVelocity(0.0);
    slider->setMaxLinMotorForce(0.0);
    return slider;
  }
  // With the reference frame A (the parent's), Bullet's hinge angle is the child's turn about the
  // axis relative to the parent, positive by the right hand: the URDF joint's position.
  auto hinge = std::make_unique<btHingeConstraint>(a, b, toBullet(in_parent), toBullet(in_child), true);
  if (joint.kind == JointKind::kRevolute)
  {
    // Bullet's limit arguments: softness (unused by its solver), the bias (30 % of an overshoot
    // corrected per step) and the relaxation, which its solver applies as the stop's restitution:
    // 0, a door does not bounce off its stop.
    hinge->setLimit(joint.lower, joint.upper, 0.9, 0.3, 0.0);
  }
  hinge->enableAngularMotor(true, 0.0, 0.0);
  return hinge;
}

void resistJointMotion(const JointDescription& joint, const JointState& state, double time_step,
                       btTypedConstraint* constraint)
{
  const double resistance = joint.friction + joint.damping * std::abs(state.velocity);  // N or N m
  if (joint.kind == JointKind::kPrismatic)
  {
    static_cast<btSliderConstraint*>(constraint)->setMaxLinMotorForce(resistance);
  }
  else
  {
    static_cast<btHingeConstraint*>(constraint)->setMaxMotorImpulse(resistance * time_step);
  }
}
}  // namespace god_finger::internal
