#include "god_finger/scenarios/mug_grasp_task.h"
#include "task_world.h"

#include "god_finger/haptics/waypoint_path.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/urdf_scene.h"
#include "god_finger/support/input_error.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

namespace god_finger
{
namespace
{
// The script's times (s) and the hand's geometry, see the header.
constexpr double kClosed = 1.0;
constexpr double kLiftStart = 1.5;
constexpr double kLiftEnd = 3.5;
constexpr double kEnd = 4.5;
constexpr double kOpenRadius = 0.07;  // m, the fingers' targets off the axis, open
constexpr double kWallRadius = 0.04;  // m, the mug's outer radius (urdf/meshes/mug.obj)
constexpr double kGripHeight = 0.05;  // m
constexpr int kFingers = 3;
constexpr std::array<double, kFingers> kFingerDegrees = {60.0, 180.0, 300.0};
constexpr int kMisalignedFinger = 1;  // the one at 180 degrees, closing along x
constexpr double kPi = 3.141592653589793;

Eigen::Vector3d outwards(int finger)
{
  const double angle = kFingerDegrees[finger] * kPi / 180.0;
  return Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0);
}
}  // namespace

MugGraspResult runMugGrasp(const MugGraspOptions& options)
{
  TaskWorld task(
      "mug grasp", "squeeze", options.squeeze, 0.03,
      [&options]() { return loadUrdfScene(options.scenes_dir + "/table_mug.urdf"); }, options.params, options.model,
      "mug");
  GodFingerWorld& world = task.world;
  const int mug = task.object;
  const OperatorTraits& traits = options.hand;
  const double face = kWallRadius + options.params.coupling.proxy_radius;  // proxy centre on the wall
  auto target = [&](double t, double squeeze_factor, int finger) -> Eigen::Vector3d
  {
    const double closed = minimumJerkRamp(t, 0.0, kClosed);
    const double radius = kOpenRadius + (face - options.squeeze * squeeze_factor - kOpenRadius) * closed;
    const Eigen::Vector3d centre(0.0, 0.0, kGripHeight + kMugLift * minimumJerkRamp(t, kLiftStart, kLiftEnd));
    Eigen::Vector3d position = centre + radius * outwards(finger) + tremorAt(traits, t, finger);
    if (finger == kMisalignedFinger)
    {
      position += traits.misalignment;
    }
    return position;
  };
  std::array<int, kFingers> fingers{};
  for (int k = 0; k < kFingers; ++k)
  {
    fingers[k] = world.addInterface(target(0.0, 1.0, k));
  }
  const double start_z = world.bodyState(mug).center_of_mass.z();
  const double dt = world.params().time_step;
  GripReflex reflex(traits.reaction_delay);
  MugGraspResult result;
  result.held = true;
  std::array<Eigen::Vector3d, kFingers> grip_on_mug{};  // mug frame, fixed at the lift's start
  std::array<Eigen::Vector3d, kFingers> previous_slip{};
  previous_slip.fill(Eigen::Vector3d::Zero());
  double extra = 0.0;
  double force_sum = 0.0;
  long force_samples = 0;
  bool lifting = false;
  for (long i = 0; i < std::lround(kEnd / dt); ++i)
  {
    const double t = (i + 1) * dt;
    const double factor = fluctuationAt(traits, t) + extra;
    for (int k = 0; k < kFingers; ++k)
    {
      world.setInterfaceTarget(fingers[k], target(t, factor, k));
    }
    world.step();
    const BodyState state = world.bodyState(mug);
    if (!lifting && t >= kLiftStart)
    {
      lifting = true;
      for (int k = 0; k < kFingers; ++k)
      {
        grip_on_mug[k] = state.pose.inverse() * world.interfaceState(fingers[k]).proxy_position;
      }
    }
    if (!lifting)
    {
      continue;
    }
    const Eigen::Vector3d axis = state.pose.linear().col(2);
    double fastest = 0.0;
    for (int k = 0; k < kFingers; ++k)
    {
      const InterfaceState& finger = world.interfaceState(fingers[k]);
      Eigen::Vector3d radial = finger.proxy_position - state.pose.translation();
      radial -= radial.dot(axis) * axis;
      radial.normalize();
      // Along the wall only: tremor moves the finger in and out of a held wall.
      Eigen::Vector3d slip = state.pose * grip_on_mug[k] - finger.proxy_position;
      slip -= slip.dot(radial) * radial;
      result.max_slip_m = std::max(result.max_slip_m, slip.norm());
      fastest = std::max(fastest, (slip - previous_slip[k]).norm() / dt);
      previous_slip[k] = slip;
      if (t >= kLiftEnd)
      {
        force_sum += std::abs(finger.user_force.dot(radial));
        ++force_samples;
      }
    }
    extra = reflex.update(t, fastest);
    result.max_tilt_rad = std::max(result.max_tilt_rad, std::acos(std::clamp(axis.z(), -1.0, 1.0)));
    if (t >= kLiftEnd && state.center_of_mass.z() < start_z + 0.5 * kMugLift)
    {
      result.held = false;
    }
  }
  result.lift_height_m = world.bodyState(mug).center_of_mass.z() - start_z;
  result.mean_grip_force_N = force_samples > 0 ? force_sum / force_samples : 0.0;
  result.lifted = result.held && result.max_tilt_rad <= kMugTiltTolerance;
  return result;
}
}  // namespace god_finger
