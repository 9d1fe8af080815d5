#include "god_finger/scenarios/joint_metrics.h"

#include "god_finger/support/input_error.h"

#include <algorithm>
#include <cmath>

namespace god_finger
{
JointMetrics::JointMetrics(const SceneDescription& scene, const ScenarioTimes& times) : times_(times)
{
  if (scene.joints.empty())
  {
    throw InputError("scene '" + scene.name + "' has no joint to measure");
  }
  joint_ = scene.joints.front();
}

void JointMetrics::add(double time, const GodFingerWorld& world)
{
  const JointState state = world.jointState(0);
  position_ = state.position;
  if (joint_.kind != JointKind::kContinuous)
  {
    beyond_limit_ = std::max({beyond_limit_, state.position - joint_.upper, joint_.lower - state.position});
  }
  if (world.interfaceCount() < 1 || time < times_.lift_start || time > times_.lift_end)
  {
    return;
  }
  const InterfaceState& finger = world.interfaceState(0);
  const Eigen::Isometry3d parent_pose =
      joint_.parent < 0 ? Eigen::Isometry3d::Identity() : world.bodyState(joint_.parent).pose;
  const Eigen::Isometry3d joint_frame = parent_pose * joint_.joint_in_parent;
  const Eigen::Vector3d axis = joint_frame.linear() * joint_.axis;
  // Along the motion at the finger: the axis for a slide; for a hinge, the direction the
  // finger's point of the door moves in (axis x lever arm).
  Eigen::Vector3d along = axis;
  double lever = 1.0;
  if (joint_.kind != JointKind::kPrismatic)
  {
    Eigen::Vector3d arm = finger.proxy_position - joint_frame.translation();
    arm -= arm.dot(axis) * axis;
    lever = arm.norm();
    along = lever > 0.0 ? Eigen::Vector3d(axis.cross(arm) / lever) : Eigen::Vector3d::Zero();
  }
  const double finger_along = finger.proxy_position.dot(axis);
  if (!started_)
  {
    started_ = true;
    start_position_ = state.position;
    start_finger_ = finger_along;
  }
  finger_travel_ = finger_along - start_finger_;
  joint_travel_ = state.position - start_position_;
  // The middle half of the motion: past the start's acceleration, before the stop.
  const double span = times_.lift_end - times_.lift_start;
  if (time >= times_.lift_start + 0.25 * span && time <= times_.lift_end - 0.25 * span)
  {
    // The hand feels -(force on the proxy): a hand pushing the door along feels it back.
    force_sum_ += -finger.user_force.dot(along);
    speed_sum_ += std::abs(state.velocity);
    lever_sum_ += lever;
    ++samples_;
  }
}

std::map<std::string, double> JointMetrics::metrics() const
{
  const double force = samples_ > 0 ? force_sum_ / samples_ : 0.0;
  const double speed = samples_ > 0 ? speed_sum_ / samples_ : 0.0;
  const double lever = samples_ > 0 ? lever_sum_ / samples_ : 1.0;
  const double resistance = lever > 0.0 ? (joint_.friction + joint_.damping * speed) / lever : 0.0;
  std::map<std::string, double> result = {
      {"beyond_limit", beyond_limit_}, {"hand_force_N", force}, {"resistance_force_N", resistance}};
  if (joint_.kind == JointKind::kPrismatic)
  {
    result["pulled_m"] = position_;
    result["slip_m"] = finger_travel_ - joint_travel_;
  }
  else
  {
    result["opened_rad"] = position_;
  }
  return result;
}
}  // namespace god_finger
