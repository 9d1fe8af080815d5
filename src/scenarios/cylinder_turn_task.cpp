#include "god_finger/scenarios/cylinder_turn_task.h"
#include "task_world.h"

#include "god_finger/haptics/waypoint_path.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/support/input_error.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

namespace god_finger
{
namespace
{
// The script's times (s), see the header.
constexpr double kClosed = 1.0;
constexpr double kLiftStart = 1.5;
constexpr double kLiftEnd = 2.5;
constexpr double kTurnEnd = 4.5;
constexpr double kEnd = 5.5;
constexpr double kOpenGap = 0.015;  // m, each finger's target outside the mantle, open
constexpr double kPi = 3.141592653589793;

// The finger's direction from the axis at angle `angle` (rad) about +z from +x.
Eigen::Vector3d around(double angle)
{
  return Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0);
}

// The body's turn about z from its start: the heading of its x axis.
double heading(const Eigen::Isometry3d& pose)
{
  const Eigen::Vector3d x_axis = pose.linear().col(0);
  return std::atan2(x_axis.y(), x_axis.x());
}
}  // namespace

SceneDescription cylinderTurnScene()
{
  SceneDescription scene;
  scene.name = "cylinder_turn";
  BodyDescription cylinder = cylinderBody("cylinder", kTurnCylinderRadius, kTurnCylinderLength, kTurnCylinderMass,
                                          Eigen::Vector3d(0, 0, 0.5 * kTurnCylinderLength));
  cylinder.material.friction = kTurnCylinderFriction;
  scene.bodies = {boxBody("table", Eigen::Vector3d(0.6, 0.6, 0.04), 0.0, Eigen::Vector3d(0, 0, -0.02)), cylinder};
  return scene;
}

CylinderTurnResult runCylinderTurn(const CylinderTurnOptions& options)
{
  TaskWorld task("cylinder turn", "squeeze", options.squeeze, 0.05, cylinderTurnScene, options.params, options.model,
                 "cylinder");
  GodFingerWorld& world = task.world;
  const int cylinder = task.object;
  const OperatorTraits& traits = options.hand;
  const double face = kTurnCylinderRadius + options.params.coupling.proxy_radius;  // proxy centre on the mantle
  const double start_z = world.bodyState(cylinder).center_of_mass.z();
  // Finger 0 starts at -y, finger 1 (the misaligned one) at +y; both go +90 degrees about z.
  const std::array<double, 2> start_angle = {-0.5 * kPi, 0.5 * kPi};
  auto target = [&](double t, double squeeze_factor, int finger) -> Eigen::Vector3d
  {
    const double closed = minimumJerkRamp(t, 0.0, kClosed);
    const double open = face + kOpenGap;
    const double radius = open + (face - options.squeeze * squeeze_factor - open) * closed;
    const double turned = kTurnAngle * minimumJerkRamp(t, kLiftEnd, kTurnEnd);
    const Eigen::Vector3d centre(0.0, 0.0, start_z + kTurnLift * minimumJerkRamp(t, kLiftStart, kLiftEnd));
    Eigen::Vector3d position = centre + radius * around(start_angle[finger] + turned) + tremorAt(traits, t, finger);
    if (finger == 1)
    {
      position += Eigen::AngleAxisd(turned, Eigen::Vector3d::UnitZ()) * traits.misalignment;
    }
    return position;
  };
  // An oriented finger: its pulp (z) towards the axis, its tip (x) down, turned with the hand.
  auto fingerOrientation = [&](double t, int finger) -> Eigen::Quaterniond
  {
    const double turned = kTurnAngle * minimumJerkRamp(t, kLiftEnd, kTurnEnd);
    Eigen::Matrix3d frame;
    frame.col(0) = -Eigen::Vector3d::UnitZ();
    frame.col(2) = -around(start_angle[finger] + turned);
    frame.col(1) = frame.col(2).cross(frame.col(0));
    const Eigen::Vector3d shake = wristTremorAt(traits, t, finger);
    const double angle = shake.norm();
    const Eigen::Matrix3d wrist =
        angle > 0.0 ? Eigen::AngleAxisd(angle, shake / angle).toRotationMatrix() : Eigen::Matrix3d::Identity();
    return Eigen::Quaterniond(wrist * frame);
  };
  std::array<int, 2> fingers{};
  for (int k = 0; k < 2; ++k)
  {
    fingers[k] = world.addInterface(target(0.0, 1.0, k));
  }
  const double dt = world.params().time_step;
  GripReflex reflex(traits.reaction_delay);
  CylinderTurnResult result;
  result.held = true;
  std::array<double, 2> slip{0.0, 0.0};  // m, sliding path per finger since the lift's start
  // Each finger's proxy orientation at the last step (the identity for a 3-DOF finger).
  std::array<Eigen::Quaterniond, 2> last_finger_orientation{Eigen::Quaterniond::Identity(),
                                                            Eigen::Quaterniond::Identity()};
  double extra = 0.0;
  double force_sum = 0.0;
  long force_samples = 0;
  double last_heading = heading(world.bodyState(cylinder).pose);
  double turn = 0.0;
  for (long i = 0; i < std::lround(kEnd / dt); ++i)
  {
    const double t = (i + 1) * dt;
    const double factor = fluctuationAt(traits, t) + extra;
    for (int k = 0; k < 2; ++k)
    {
      if (options.oriented)
      {
        world.setInterfaceTarget(fingers[k], target(t, factor, k), fingerOrientation(t, k));
      }
      else
      {
        world.setInterfaceTarget(fingers[k], target(t, factor, k));
      }
    }
    world.step();
    const BodyState state = world.bodyState(cylinder);
    // Unwrapped: a turn past 180 degrees stays one number.
    const double now = heading(state.pose);
    turn += std::remainder(now - last_heading, 2.0 * kPi);
    last_heading = now;
    std::array<Eigen::Vector3d, 2> finger_spin;  // rad/s, world: each proxy's turn this step
    for (int k = 0; k < 2; ++k)
    {
      const Eigen::Quaterniond& now_orientation = world.interfaceState(fingers[k]).proxy_orientation;
      const Eigen::AngleAxisd finger_turn(now_orientation * last_finger_orientation[k].conjugate());
      last_finger_orientation[k] = now_orientation;
      finger_spin[k] = finger_turn.angle() / dt * finger_turn.axis();
    }
    if (t < kLiftStart)
    {
      continue;
    }
    const Eigen::Vector3d axis = state.pose.linear().col(2);
    double fastest = 0.0;
    for (int k = 0; k < 2; ++k)
    {
      const InterfaceState& finger = world.interfaceState(fingers[k]);
      Eigen::Vector3d radial = finger.proxy_position - state.center_of_mass;
      radial -= radial.dot(axis) * axis;
      radial.normalize();
      // The mantle's point under the finger; slip is the finger's velocity against it, along the
      // surface (rolling is no slip; tremor in and out of the mantle is none either).
      // An oriented finger's pad turns with it (pad_state.h): its material point there moves
      // with the finger's turn too.
      const Eigen::Vector3d contact = finger.proxy_position - options.params.coupling.proxy_radius * radial;
      Eigen::Vector3d relative = finger.proxy_velocity + finger_spin[k].cross(contact - finger.proxy_position) -
                                 state.linear_velocity - state.angular_velocity.cross(contact - state.center_of_mass);
      relative -= relative.dot(radial) * radial;
      slip[k] += relative.norm() * dt;
      fastest = std::max(fastest, relative.norm());
      if (t >= kLiftEnd)
      {
        force_sum += std::abs(finger.user_force.dot(radial));
        ++force_samples;
      }
    }
    extra = reflex.update(t, fastest);
    result.final_tilt_rad = std::acos(std::clamp(axis.z(), -1.0, 1.0));
    result.max_tilt_rad = std::max(result.max_tilt_rad, result.final_tilt_rad);
    if (t >= kLiftEnd && state.center_of_mass.z() < start_z + 0.5 * kTurnLift)
    {
      result.held = false;
    }
  }
  result.max_slip_m = std::max(slip[0], slip[1]);
  result.turn_rad = turn;
  result.mean_grip_force_N = force_samples > 0 ? force_sum / force_samples : 0.0;
  result.turned = result.held && std::abs(result.turn_rad - kTurnAngle) <= kTurnTolerance &&
                  result.final_tilt_rad <= kTurnTiltTolerance;
  return result;
}
}  // namespace god_finger
