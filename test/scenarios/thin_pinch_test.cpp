// A free bar pinched across its thickness in mid-air and lifted, for thicknesses from 1 to
// 30 mm (issue 24: god_finger dropped every pinched bar thinner than 2.2 cm, because its overlap
// push took the two pads on opposite faces for overlapping areas and pushed the fingers apart).
//
// The set-up (thinPinch): a 100 g bar of 0.3 x t x 0.04 m (long axis x, its thickness t along y,
// mu 0.8) at rest in mid-air, its centre at (0, 0, 0.2). Two fingers start on its faces, their
// proxies touching, and are pulled 1 cm into it by the default coupling (about 3.9 N each); the
// pinch engages from the first step, with gravity. They hold 0.5 s, lift 5 cm in 1 s and hold
// until 3 s. Slip is how far the bar's centre moves against the two proxies' mid-point; turn is
// the bar's largest rotation from its start, any axis.
// Every model (god_object, soft_finger, god_finger with both pad solvers) must hold every bar with
// at most 2 mm slip and 0.01 rad turn, with the default overlap push on.
#include "god_finger/haptics/waypoint_path.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scenarios/pad_fidelity.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace god_finger
{
namespace
{
constexpr double kBarMass = 0.1;      // kg
constexpr double kBarHeight = 0.2;    // m, the bar's centre at the start
constexpr double kSqueeze = 0.01;     // m, each hand's target inside the proxy's rest on the face
constexpr double kLift = 0.05;        // m
constexpr double kLiftStart = 0.5;    // s
constexpr double kLiftEnd = 1.5;      // s
constexpr double kDuration = 3.0;     // s
constexpr double kSlipLimit = 0.002;  // m
constexpr double kTurnLimit = 0.01;   // rad

SceneDescription thinBarScene(double thickness)
{
  SceneDescription scene;
  scene.name = "thin_bar";
  scene.bodies.push_back(
      boxBody("bar", Eigen::Vector3d(0.3, thickness, 0.04), kBarMass, Eigen::Vector3d(0.0, 0.0, kBarHeight)));
  return scene;
}

struct PinchLayout
{
  const char* name;
  ContactModel model;
  PadSolver pad_solver;
};
constexpr PinchLayout kLayouts[] = {
    {"god_object", ContactModel::kGodObject, PadSolver::kConstraint},
    {"soft_finger", ContactModel::kSoftFinger, PadSolver::kConstraint},
    {"god_finger", ContactModel::kGodFinger, PadSolver::kConstraint},
    {"god_finger/points", ContactModel::kGodFinger, PadSolver::kPoints},
};

struct ThinPinch
{
  bool held = false;        // the bar ended lifted with the hands (within 1 cm of the lift)
  double slip_m = 0.0;      // largest distance of its centre from its start against the proxies' mid-point
  double turn_rad = 0.0;    // largest rotation from its start
  double overlap_m2 = 0.0;  // largest overlap area measured on either finger
};

struct World
{
  GodFingerWorld world;
  int near = -1;
  int far = -1;
  double face = 0.0;  // m: a proxy's centre at rest on a face, from the bar's mid-plane
  World(double thickness, const WorldParams& params)
      : world(thinBarScene(thickness), params), face(0.5 * thickness + params.coupling.proxy_radius)
  {
    near = world.addInterface(Eigen::Vector3d(0.0, -face, kBarHeight));
    far = world.addInterface(Eigen::Vector3d(0.0, face, kBarHeight));
  }
  void target(double t)
  {
    const double z = kBarHeight + kLift * minimumJerkRamp(t, kLiftStart, kLiftEnd);
    world.setInterfaceTarget(near, Eigen::Vector3d(0.0, -face + kSqueeze, z));
    world.setInterfaceTarget(far, Eigen::Vector3d(0.0, face - kSqueeze, z));
  }
  Eigen::Vector3d gripCentre() const
  {
    return 0.5 * (world.interfaceState(near).proxy_position + world.interfaceState(far).proxy_position);
  }
};

WorldParams layoutParams(const PinchLayout& layout)
{
  WorldParams params;
  params.model = layout.model;
  params.pad_solver = layout.pad_solver;
  return params;
}

ThinPinch thinPinch(double thickness, const PinchLayout& layout)
{
  World w(thickness, layoutParams(layout));
  const Eigen::Vector3d offset = w.world.bodyState(0).center_of_mass - w.gripCentre();
  const Eigen::Quaterniond start(w.world.bodyState(0).pose.linear());
  ThinPinch result;
  const long steps = std::lround(kDuration / w.world.params().time_step);
  for (long i = 0; i < steps; ++i)
  {
    w.target((i + 1) * w.world.params().time_step);
    w.world.step();
    const BodyState bar = w.world.bodyState(0);
    result.slip_m = std::max(result.slip_m, (bar.center_of_mass - w.gripCentre() - offset).norm());
    result.turn_rad = std::max(result.turn_rad, Eigen::Quaterniond(bar.pose.linear()).angularDistance(start));
    result.overlap_m2 = std::max(
        {result.overlap_m2, w.world.interfaceState(w.near).overlap_area, w.world.interfaceState(w.far).overlap_area});
  }
  result.held = std::abs(w.world.bodyState(0).center_of_mass.z() - (kBarHeight + kLift)) < 0.01;
  return result;
}

constexpr double kThicknesses[] = {0.001, 0.002, 0.004, 0.008, 0.012, 0.016, 0.02, 0.024, 0.03};

TEST(ThinPinch, EveryModelHoldsAFreeBarOfAnyThicknessWithoutSlipOrTurn)
{
  for (const PinchLayout& layout : kLayouts)
  {
    for (const double thickness : kThicknesses)
    {
      SCOPED_TRACE(std::string(layout.name) + " t " + std::to_string(thickness));
      const ThinPinch pinch = thinPinch(thickness, layout);
      std::printf("[ thin pinch %-17s t %4.1f mm ] %s, slip %.2f mm, turn %.4f rad, overlap %.3g m^2\n", layout.name,
                  thickness * 1e3, pinch.held ? "held" : "dropped", pinch.slip_m * 1e3, pinch.turn_rad,
                  pinch.overlap_m2);
      EXPECT_TRUE(pinch.held);
      EXPECT_LE(pinch.slip_m, kSlipLimit);
      EXPECT_LE(pinch.turn_rad, kTurnLimit);
      // Pads on opposite faces share no surface: no overlap, however thin the bar.
      EXPECT_EQ(pinch.overlap_m2, 0.0);
    }
  }
}

// The twist the held bar resists about the pinch normal (y): the largest torque that, applied
// for 0.5 s after a 1 s hold, turns it less than 1 mrad (bisection); against the two pads'
// uniform disks, 2 x (2/3) mu N a with the pads' measured N and a.
struct TwistCapacity
{
  double capacity = 0.0;  // N m
  double disks = 0.0;     // N m
};

bool holdsTwist(double thickness, double torque, double* disks)
{
  World w(thickness, layoutParams(kLayouts[2]));
  const double dt = w.world.params().time_step;
  for (long i = 0; i < std::lround(1.0 / dt); ++i)
  {
    w.target(0.0);
    w.world.step();
  }
  double sum = 0.0;
  for (const int finger : {w.near, w.far})
  {
    const InterfaceState& state = w.world.interfaceState(finger);
    if (state.contact_count != 1)
    {
      return false;
    }
    sum += uniformPadTorque(0.8, std::abs(state.user_force.y()), state.contacts[0].radius);
  }
  *disks = sum;
  const Eigen::Quaterniond start(w.world.bodyState(0).pose.linear());
  for (long i = 0; i < std::lround(0.5 / dt); ++i)
  {
    w.target(0.0);
    w.world.applyBodyWrench(0, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, torque, 0.0));
    w.world.step();
  }
  return Eigen::Quaterniond(w.world.bodyState(0).pose.linear()).angularDistance(start) < 1e-3;
}

TwistCapacity twistCapacity(double thickness)
{
  TwistCapacity result;
  double low = 0.0;
  double high = 0.1;
  for (int i = 0; i < 9; ++i)
  {
    const double mid = 0.5 * (low + high);
    double disks = 0.0;
    (holdsTwist(thickness, mid, &disks) ? low : high) = mid;
    result.disks = std::max(result.disks, disks);
  }
  result.capacity = low;
  return result;
}

TEST(ThinPinch, AThinBarResistsTheTwistOfTwoUniformDisksAsAThickOneDoes)
{
  const TwistCapacity thin = twistCapacity(0.02);
  const TwistCapacity thick = twistCapacity(0.03);
  std::printf("[ thin pinch twist ] 20 mm: %.4f N m = %.2f x the disks; 30 mm: %.4f N m = %.2f x the disks\n",
              thin.capacity, thin.capacity / thin.disks, thick.capacity, thick.capacity / thick.disks);
  ASSERT_GT(thin.disks, 0.0);
  ASSERT_GT(thick.disks, 0.0);
  EXPECT_NEAR(thin.capacity / thin.disks, 1.0, 0.1);
  EXPECT_NEAR(thin.capacity / thin.disks, thick.capacity / thick.disks, 0.05);
}
}  // namespace
}  // namespace god_finger
