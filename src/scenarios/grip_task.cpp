#include "god_finger/scenarios/grip_task.h"
#include "task_world.h"

#include "god_finger/haptics/waypoint_path.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/support/input_error.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace god_finger
{
namespace
{
// The script's times (s), see the header.
constexpr double kClosed = 1.0;
constexpr double kLiftStart = 1.5;
constexpr double kHoldLiftEnd = 3.5;
constexpr double kHoldEnd = 6.0;
constexpr double kCarryLiftEnd = 3.0;
constexpr double kCarryEnd = 5.0;
constexpr double kLowered = 6.5;
constexpr double kRelease = 7.0;
constexpr double kOpened = 7.5;
constexpr double kRisen = 8.0;
constexpr double kPlaceEnd = 8.5;
constexpr double kCarryDistance = 0.15;  // m along -x
constexpr double kLower = kGripLift + 0.002;
constexpr double kOpen = 0.04;        // m, each finger's distance from the bar's mid-plane, open
constexpr double kGripHeight = 0.02;  // m

// Where the hand's grip centre is (without tremor) and how closed it is (0 open, 1 closed).
struct HandPose
{
  Eigen::Vector3d centre;
  double closed = 0.0;
};

HandPose handAt(double t, bool carry)
{
  HandPose hand;
  hand.centre = Eigen::Vector3d(kGripOffset, 0.0, kGripHeight);
  if (!carry)
  {
    hand.closed = minimumJerkRamp(t, 0.0, kClosed);
    hand.centre.z() += kGripLift * minimumJerkRamp(t, kLiftStart, kHoldLiftEnd);
    return hand;
  }
  hand.closed = minimumJerkRamp(t, 0.0, kClosed) * (1.0 - minimumJerkRamp(t, kRelease, kOpened));
  hand.centre.z() += kGripLift * minimumJerkRamp(t, kLiftStart, kCarryLiftEnd) -
                     kLower * minimumJerkRamp(t, kCarryEnd, kLowered) + 0.05 * minimumJerkRamp(t, kOpened, kRisen);
  hand.centre.x() -= kCarryDistance * minimumJerkRamp(t, kCarryLiftEnd, kCarryEnd);
  return hand;
}
}  // namespace

SceneDescription gripBarScene()
{
  SceneDescription scene;
  scene.name = "grip_bar";
  BodyDescription bar =
      boxBody("bar", Eigen::Vector3d(0.2, kGripBarWidth, 0.04), kGripBarMass, Eigen::Vector3d(0, 0, 0.02));
  bar.material.friction = kGripBarFriction;
  scene.bodies = {boxBody("table", Eigen::Vector3d(0.6, 0.6, 0.04), 0.0, Eigen::Vector3d(0, 0, -0.02)), bar};
  return scene;
}

double gripTaskDuration(const GripTaskOptions& options)
{
  return options.carry ? kPlaceEnd : kHoldEnd;
}

void gripTargets(const GripTaskOptions& options, double t, double squeeze_factor, Eigen::Vector3d* near,
                 Eigen::Vector3d* far)
{
  const OperatorTraits& traits = options.hand;
  const double face = 0.5 * kGripBarWidth + options.params.coupling.proxy_radius;  // proxy centre on a face
  const Eigen::Vector3d across = Eigen::Vector3d::UnitY();
  const HandPose hand = handAt(t, options.carry);
  const double half = kOpen + (face - options.squeeze * squeeze_factor - kOpen) * hand.closed;
  *near = hand.centre - half * across + tremorAt(traits, t, 0);
  *far = hand.centre + half * across + traits.misalignment + tremorAt(traits, t, 1);
}

GripTaskMeter::GripTaskMeter(const GripTaskOptions& options, const Eigen::Isometry3d& start_pose,
                             const Eigen::Vector3d& start_com)
    : options_(options),
      reflex_(options.hand.reaction_delay),
      start_rotation_(start_pose.linear()),
      start_z_(start_com.z())
{
  result_.held = true;
  result_.min_squeeze_m = INFINITY;
}

double GripTaskMeter::squeezeFactor(double t) const
{
  return fluctuationAt(options_.hand, t) + extra_;
}

void GripTaskMeter::add(double t, double squeeze_factor, const Eigen::Isometry3d& bar_pose,
                        const Eigen::Vector3d& bar_com, const Eigen::Vector3d& near_proxy,
                        const Eigen::Vector3d& far_proxy, const Eigen::Vector3d& near_force,
                        const Eigen::Vector3d& far_force)
{
  const Eigen::Vector3d across = Eigen::Vector3d::UnitY();
  const double hold_end = options_.carry ? kRelease : kHoldEnd;
  const Eigen::Vector3d midpoint = 0.5 * (near_proxy + far_proxy);
  if (!lifting_ && t >= kLiftStart)
  {
    lifting_ = true;
    grip_on_bar_ = bar_pose.inverse() * midpoint;
  }
  if (!lifting_ || t > hold_end)
  {
    return;
  }
  // Slip across the pinch only: along it, tremor moves the fingers' midpoint on a held bar.
  Eigen::Vector3d slip = bar_pose * grip_on_bar_ - midpoint;
  slip -= slip.dot(across) * across;
  result_.max_slip_m = std::max(result_.max_slip_m, slip.norm());
  extra_ = reflex_.update(t, (slip - previous_slip_).norm() / options_.params.time_step);
  previous_slip_ = slip;
  const Eigen::AngleAxisd turned(bar_pose.linear() * start_rotation_.transpose());
  const Eigen::Vector3d rotation = turned.angle() * turned.axis();
  result_.final_turn_rad = std::abs(rotation.y());
  result_.max_turn_rad = std::max(result_.max_turn_rad, result_.final_turn_rad);
  result_.max_tilt_rad = std::max(result_.max_tilt_rad, std::hypot(rotation.x(), rotation.z()));
  const bool lifted = t >= (options_.carry ? kCarryLiftEnd : kHoldLiftEnd);
  if (lifted && bar_com.z() < start_z_ + 0.5 * kGripLift && t <= (options_.carry ? kCarryEnd : hold_end))
  {
    result_.held = false;
  }
  if (lifted)
  {
    force_sum_ += 0.5 * (std::abs(near_force.dot(across)) + std::abs(far_force.dot(across)));
    ++force_samples_;
    result_.min_squeeze_m = std::min(result_.min_squeeze_m, options_.squeeze * squeeze_factor);
  }
}

GripTaskResult GripTaskMeter::finish(const Eigen::Isometry3d& bar_pose, const Eigen::Vector3d& bar_com)
{
  GripTaskResult result = result_;
  result.mean_grip_force_N = force_samples_ > 0 ? force_sum_ / force_samples_ : 0.0;
  result.final_rotation_rad = Eigen::AngleAxisd(bar_pose.linear() * start_rotation_.transpose()).angle();
  if (options_.carry)
  {
    const Eigen::Vector3d target(-kCarryDistance, 0.0, start_z_);
    result.placed_error_m = (bar_com - target).norm();
    // Lying as it started: a bar swung over end to end may land within 2 cm, reversed.
    result.placed = result.held && result.placed_error_m < 0.02 && result.final_rotation_rad < 0.2;
  }
  return result;
}

GripTaskResult runGripTask(const GripTaskOptions& options)
{
  TaskWorld task("grip task", "squeeze", options.squeeze, 0.1, gripBarScene, options.params, options.model, "bar");
  GodFingerWorld& world = task.world;
  const int bar = task.object;
  Eigen::Vector3d near, far;
  gripTargets(options, 0.0, 1.0, &near, &far);
  const int near_finger = world.addInterface(near);
  const int far_finger = world.addInterface(far);
  GripTaskMeter meter(options, world.bodyState(bar).pose, world.bodyState(bar).center_of_mass);
  const double dt = world.params().time_step;
  for (long i = 0; i < std::lround(gripTaskDuration(options) / dt); ++i)
  {
    const double t = (i + 1) * dt;
    const double factor = meter.squeezeFactor(t);
    gripTargets(options, t, factor, &near, &far);
    world.setInterfaceTarget(near_finger, near);
    world.setInterfaceTarget(far_finger, far);
    world.step();
    const BodyState state = world.bodyState(bar);
    meter.add(t, factor, state.pose, state.center_of_mass, world.interfaceState(near_finger).proxy_position,
              world.interfaceState(far_finger).proxy_position, world.interfaceState(near_finger).user_force,
              world.interfaceState(far_finger).user_force);
  }
  return meter.finish(world.bodyState(bar).pose, world.bodyState(bar).center_of_mass);
}
}  // namespace god_finger
