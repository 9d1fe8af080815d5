#include "god_finger/physics/pad_fidelity.h"

#include "god_finger/physics/god_finger_world.h"

#include <cmath>
#include <functional>
#include <memory>

namespace god_finger
{
namespace
{
constexpr double kSettle = 0.5;  // s before any torque
constexpr double kBoxHeight = 0.02;

SceneDescription twistScene(double friction)
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
  scene.name = "twist";
  scene.bodies = {table, box};
  return scene;
}

double yaw(const BodyState& state)
{
  const Eigen::Matrix3d& r = state.pose.linear();
  return std::atan2(r(1, 0), r(0, 0));
}

// Builds the world, settles the press, then steps with torque(t) (t from the end of settling)
// until `stop` returns true or `duration` is over; returns the measurement with the rotation.
TwistMeasurement run(const TwistSetup& setup, double duration, const std::function<double(double)>& torque,
                     const std::function<bool(double, double, TwistMeasurement*)>& stop)
{
  WorldParams params = setup.params;
  params.model = setup.model;
  GodFingerWorld world(twistScene(setup.friction), params);
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
    world.step();
  }
  TwistMeasurement result;
  const InterfaceState& state = world.interfaceState(finger);
  result.normal_force = std::abs(state.user_force.z());
  result.contact_radius = state.contact_count > 0 ? state.contacts[0].radius : 0.0;
  const double start = yaw(world.bodyState(1));
  const long steps = std::lround(duration / dt);
  for (long i = 0; i < steps; ++i)
  {
    const double t = i * dt;
    world.applyBodyWrench(1, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, torque(t)));
    world.step();
    result.rotation = yaw(world.bodyState(1)) - start;
    if (stop(t, torque(t), &result))
    {
      return result;
    }
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

TwistMeasurement measureTwistSlip(const TwistSetup& setup, double torque_rate, double duration, double slip_angle)
{
  bool slipped = false;
  TwistMeasurement result = run(
      setup, duration, [torque_rate](double t) { return torque_rate * t; },
      [&](double, double torque, TwistMeasurement* m)
      {
        if (std::abs(m->rotation) >= slip_angle)
        {
          m->slip_torque = torque;
          slipped = true;
        }
        return slipped;
      });
  if (!slipped)
  {
    result.slip_torque = INFINITY;
  }
  return result;
}

TwistMeasurement measureTwistHold(const TwistSetup& setup, double torque, double duration)
{
  return run(
      setup, duration, [torque](double) { return torque; }, [](double, double, TwistMeasurement*) { return false; });
}
}  // namespace god_finger
