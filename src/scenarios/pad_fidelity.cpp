#include "god_finger/scenarios/pad_fidelity.h"

#include "god_finger/physics/god_finger_world.h"

#include <cmath>
#include <memory>

namespace god_finger
{
namespace
{
constexpr double kSettle = 0.5;  // s before any torque
constexpr double kBoxHeight = 0.02;

}  // namespace

SceneDescription padLoadScene(PadLoad load, double friction)
{
  BodyDescription table;
  table.name = "table";
  table.is_static = true;
  table.geometry.kind = GeometryKind::kBox;
  table.geometry.size = Eigen::Vector3d(1.0, 1.0, 0.05);
  table.pose.translation() = Eigen::Vector3d(0.0, 0.0, -0.025);
  table.material.friction = 0.0;  // only the finger resists the twist
  BodyDescription box;
  box.name = "box";
  box.geometry.kind = GeometryKind::kBox;
  box.geometry.size = Eigen::Vector3d(0.1, 0.1, kBoxHeight);
  box.mass = 0.2;
  box.inertia =
      Eigen::Vector3d(box.mass * (0.01 + 0.0004) / 12.0, box.mass * (0.01 + 0.0004) / 12.0, box.mass * 0.02 / 12.0)
          .asDiagonal();
  box.pose.translation() = Eigen::Vector3d(0.0, 0.0, 0.5 * kBoxHeight);
  box.material.friction = friction;
  SceneDescription scene;
  scene.name = load == PadLoad::kTwist ? "twist" : "tilt";
  scene.bodies = {table, box};
  if (load == PadLoad::kTilt)
  {
    scene.bodies = {box};
  }
  return scene;
}

namespace
{
// The box's turn about the load's axis (z for a twist, x for a tilt).
double turn(PadLoad load, const BodyState& state)
{
  const Eigen::Matrix3d& r = state.pose.linear();
  return load == PadLoad::kTwist ? std::atan2(r(1, 0), r(0, 0)) : std::atan2(r(2, 1), r(1, 1));
}

// Builds the world, settles the press, then steps for `duration` (s) with `torque` (N m) held
// on the box; returns the measurement with the box's turn.
PadLoadMeasurement run(const PadLoadSetup& setup, double duration, double torque)
{
  WorldParams params = setup.params;
  params.model = setup.model;
  const bool tilt = setup.load == PadLoad::kTilt;
  if (tilt)
  {
    params.gravity.setZero();
  }
  GodFingerWorld world(padLoadScene(setup.load, setup.friction), params);
  const int box = tilt ? 0 : 1;
  const double radius = params.coupling.proxy_radius;
  const double rest = kBoxHeight + radius;
  const int finger = world.addInterface(Eigen::Vector3d(0.0, 0.0, rest + 0.005));
  const double press = setup.normal_force / world.coupling(finger).stiffness;
  const double dt = params.time_step;
  const long settle_steps = std::lround(kSettle / dt);
  for (long i = 0; i < settle_steps; ++i)
  {
    const double s = std::min(1.0, (i + 1) * dt / (0.6 * kSettle));
    world.setInterfaceTarget(finger, Eigen::Vector3d(0.0, 0.0, rest + 0.005 * (1.0 - s) - press * s));
    if (tilt)
    {
      world.applyBodyWrench(box, Eigen::Vector3d(0.0, 0.0, s * setup.normal_force), Eigen::Vector3d::Zero());
    }
    world.step();
  }
  PadLoadMeasurement result;
  const InterfaceState& state = world.interfaceState(finger);
  result.normal_force = std::abs(state.user_force.z());
  result.contact_radius = state.contact_count > 0 ? state.contacts[0].radius : 0.0;
  const double start = turn(setup.load, world.bodyState(box));
  const long steps = std::lround(duration / dt);
  for (long i = 0; i < steps; ++i)
  {
    if (tilt)
    {
      world.applyBodyWrench(box, Eigen::Vector3d(0.0, 0.0, setup.normal_force), Eigen::Vector3d(torque, 0.0, 0.0));
    }
    else
    {
      world.applyBodyWrench(box, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, torque));
    }
    world.step();
    result.rotation = turn(setup.load, world.bodyState(box)) - start;
  }
  return result;
}
}  // namespace

double uniformPadTorque(double mu, double normal_force, double radius)
{
  return 2.0 / 3.0 * mu * normal_force * radius;
}

double hertzPadTorque(double mu, double normal_force, double radius)
{
  return 3.0 * M_PI / 16.0 * mu * normal_force * radius;
}

double padTiltTorque(double normal_force, double radius)
{
  return normal_force * radius;
}

PadLoadMeasurement measurePadHold(const PadLoadSetup& setup, double torque, double duration)
{
  return run(setup, duration, torque);
}
double measurePadCapacity(const PadLoadSetup& setup, double upper, double duration, double tolerance, int bisections)
{
  double held = 0.0;
  double turned = upper;
  for (int i = 0; i < bisections; ++i)
  {
    const double torque = 0.5 * (held + turned);
    (std::abs(measurePadHold(setup, torque, duration).rotation) < tolerance ? held : turned) = torque;
  }
  return held;
}
}  // namespace god_finger
