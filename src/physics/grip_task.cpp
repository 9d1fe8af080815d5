#include "god_finger/physics/grip_task.h"

#include "god_finger/core/input_error.h"
#include "god_finger/core/waypoint_path.h"
#include "god_finger/physics/god_finger_world.h"

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

GripTaskResult runGripTask(const GripTaskOptions& options)
{
  if (!(options.squeeze > 0.0 && options.squeeze <= 0.1))
  {
    throw InputError("grip task: squeeze " + std::to_string(options.squeeze) + " m is outside (0, 0.1]");
  }
  const SceneDescription scene = gripBarScene();
  GodFingerWorld world(scene, options.params);
  world.setContactModel(options.model);
  const int bar = scene.find("bar");
  const OperatorTraits& traits = options.hand;
  const double face = 0.5 * kGripBarWidth + options.params.coupling.proxy_radius;  // proxy centre on a face
  const Eigen::Vector3d across = Eigen::Vector3d::UnitY();
  auto targets = [&](double t, double squeeze_factor, Eigen::Vector3d* near, Eigen::Vector3d* far)
  {
    const HandPose hand = handAt(t, options.carry);
    const double half = kOpen + (face - options.squeeze * squeeze_factor - kOpen) * hand.closed;
    *near = hand.centre - half * across + tremorAt(traits, t, 0);
    *far = hand.centre + half * across + traits.misalignment + tremorAt(traits, t, 1);
  };
  Eigen::Vector3d near, far;
  targets(0.0, 1.0, &near, &far);
  const int near_finger = world.addInterface(near);
  const int far_finger = world.addInterface(far);
  const Eigen::Matrix3d start_rotation = world.bodyState(bar).pose.linear();
  const double start_z = world.bodyState(bar).center_of_mass.z();
  const double hold_end = options.carry ? kRelease : kHoldEnd;
  const double end = options.carry ? kPlaceEnd : kHoldEnd;
  const double dt = world.params().time_step;
  GripReflex reflex(traits.reaction_delay);
  GripTaskResult result;
  result.held = true;
  result.min_squeeze_m = INFINITY;
  Eigen::Vector3d grip_on_bar = Eigen::Vector3d::Zero();  // bar frame, fixed at the lift's start
  Eigen::Vector3d previous_slip = Eigen::Vector3d::Zero();
  double extra = 0.0;
  double force_sum = 0.0;
  long force_samples = 0;
  bool lifting = false;
  for (long i = 0; i < std::lround(end / dt); ++i)
  {
    const double t = (i + 1) * dt;
    const double factor = fluctuationAt(traits, t) + extra;
    targets(t, factor, &near, &far);
    world.setInterfaceTarget(near_finger, near);
    world.setInterfaceTarget(far_finger, far);
    world.step();
    const BodyState state = world.bodyState(bar);
    const Eigen::Vector3d midpoint =
        0.5 * (world.interfaceState(near_finger).proxy_position + world.interfaceState(far_finger).proxy_position);
    if (!lifting && t >= kLiftStart)
    {
      lifting = true;
      grip_on_bar = state.pose.inverse() * midpoint;
    }
    if (!lifting || t > hold_end)
    {
      continue;
    }
    // Slip across the pinch only: along it, tremor moves the fingers' midpoint on a held bar.
    Eigen::Vector3d slip = state.pose * grip_on_bar - midpoint;
    slip -= slip.dot(across) * across;
    result.max_slip_m = std::max(result.max_slip_m, slip.norm());
    extra = reflex.update(t, (slip - previous_slip).norm() / dt);
    previous_slip = slip;
    const Eigen::AngleAxisd turned(state.pose.linear() * start_rotation.transpose());
    const Eigen::Vector3d rotation = turned.angle() * turned.axis();
    result.final_turn_rad = std::abs(rotation.y());
    result.max_turn_rad = std::max(result.max_turn_rad, result.final_turn_rad);
    result.max_tilt_rad = std::max(result.max_tilt_rad, std::hypot(rotation.x(), rotation.z()));
    const bool lifted = t >= (options.carry ? kCarryLiftEnd : kHoldLiftEnd);
    if (lifted && state.center_of_mass.z() < start_z + 0.5 * kGripLift && t <= (options.carry ? kCarryEnd : hold_end))
    {
      result.held = false;
    }
    if (lifted)
    {
      force_sum += 0.5 * (std::abs(world.interfaceState(near_finger).user_force.dot(across)) +
                          std::abs(world.interfaceState(far_finger).user_force.dot(across)));
      ++force_samples;
      result.min_squeeze_m = std::min(result.min_squeeze_m, options.squeeze * factor);
    }
  }
  result.mean_grip_force_N = force_samples > 0 ? force_sum / force_samples : 0.0;
  result.final_rotation_rad =
      Eigen::AngleAxisd(world.bodyState(bar).pose.linear() * start_rotation.transpose()).angle();
  if (options.carry)
  {
    const Eigen::Vector3d target(-kCarryDistance, 0.0, start_z);
    result.placed_error_m = (world.bodyState(bar).center_of_mass - target).norm();
    // Lying as it started: a bar swung over end to end may land within 2 cm, reversed.
    result.placed = result.held && result.placed_error_m < 0.02 && result.final_rotation_rad < 0.2;
  }
  return result;
}
}  // namespace god_finger
