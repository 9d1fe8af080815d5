// Oriented fingers through the servo loop (issue 19 item 1): a device's orientation reaches the
// physics mapped into the world, the rotational coupling's torque comes back on the profile's
// torque axes only, saturated, a device that reports no orientation runs the 3-DOF code bit for
// bit, and no unusable orientation ever reaches the physics.
#include "allocation_counter.h"
#include "god_finger/devices/fake_device.h"
#include "god_finger/runtime/servo_loop.h"
#include "god_finger/scenarios/experiment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace god_finger
{
namespace
{
constexpr double kRoll = 40.0 * M_PI / 180.0;  // the roll_finger scenario's

ExperimentOptions rollOptions()
{
  ExperimentOptions options;
  options.scenario = Scenario::kRollFinger;
  options.scenes_dir = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes";
  return options;
}

// The roll_finger scenario's scene, world and script (scenarios/experiment.h).
ScenarioSetup rollSetup()
{
  return loadScenario(rollOptions());
}

WorldParams rollParams()
{
  return scenarioParams(rollOptions());
}

std::unique_ptr<ServoLoop> makeLoop(std::unique_ptr<HapticDevice> device, const DeviceProfile& profile,
                                    const WorkspaceMapping& mapping = {})
{
  std::vector<ServoInterface> interfaces(1);
  interfaces[0].name = "finger";
  interfaces[0].device = std::move(device);
  interfaces[0].profile = profile;
  interfaces[0].profile.coupling = rollParams().coupling;
  interfaces[0].mapping = mapping;
  ServoLoopParams params;
  params.simulated_time = true;
  params.real_time_factor = 0.0;
  auto loop = std::make_unique<ServoLoop>(std::make_unique<GodFingerWorld>(rollSetup().scene, rollParams()),
                                          std::move(interfaces), params);
  loop->prepare();
  return loop;
}

// The scenario's fake device: its finger's path, and its orientation unless `oriented` is false.
std::unique_ptr<FakeDevice> rollingHand(bool oriented = true)
{
  const ScenarioSetup setup = rollSetup();
  std::optional<OrientationPath> orientation;
  if (oriented)
  {
    orientation = setup.orientations.at(0);
  }
  auto device = std::make_unique<FakeDevice>(FakeDeviceParams(), setup.fingers.at(0), orientation);
  device->setScriptStart(0.0);
  return device;
}

// A device with the force-only interface of before (update() alone; HapticDevice's
// updateWrench() default), around a fake device.
class ForceOnly : public HapticDevice
{
 public:
  explicit ForceOnly(std::unique_ptr<FakeDevice> device) : device_(std::move(device)) {}
  std::string name() const override
  {
    return "force_only";
  }
  void start() override
  {
    device_->start();
  }
  DeviceReading update(double time, const Eigen::Vector3d& force) override
  {
    return device_->update(time, force);
  }

 private:
  std::unique_ptr<FakeDevice> device_;
};

// A device above the box whose orientation is a function of time (faults included).
class TurningDevice : public HapticDevice
{
 public:
  std::function<Eigen::Quaterniond(double)> orientation;
  std::string name() const override
  {
    return "turning";
  }
  void start() override {}
  DeviceReading update(double time, const Eigen::Vector3d& /*force*/) override
  {
    DeviceReading reading;
    reading.position = Eigen::Vector3d(0.0, 0.0, 0.09);  // in free space, 3 cm above the box
    reading.has_orientation = true;
    reading.orientation = orientation(time);
    return reading;
  }
};

// Ticks [first, first + ticks) with the samples popped into `each` (may be empty).
void run(ServoLoop& loop, long first, long ticks, const std::function<void(const ServoSample&)>& each = {})
{
  ServoSample sample;
  WorldSnapshot snapshot;
  for (long k = first; k < first + ticks; ++k)
  {
    loop.tick(static_cast<double>(k) * loop.period());
    while (loop.samples().tryPop(&sample))
    {
      if (each)
      {
        each(sample);
      }
    }
    while (loop.snapshots().tryPop(&snapshot))
    {
    }
  }
}

long ticksOf(double seconds)
{
  return std::lround(seconds / 1e-3);
}

// A finger whose device reports no orientation: exactly the force-only interface's trajectory,
// also with a profile that names torque axes; it stays a 3-DOF finger and is sent no torque.
TEST(OrientedServo, ADeviceWithoutOrientationRunsThe3DofCodeBitForBit)
{
  DeviceProfile torque_profile;
  torque_profile.torque_axes = kTorqueX | kTorqueY | kTorqueZ;
  torque_profile.max_torque = 1.0;
  auto fake = rollingHand(false);
  FakeDevice* fake_device = fake.get();
  auto a = makeLoop(std::make_unique<ForceOnly>(rollingHand(false)), DeviceProfile());
  auto b = makeLoop(std::move(fake), torque_profile);
  for (long k = 0; k < ticksOf(2.5); ++k)
  {
    run(*a, k, 1);
    run(*b, k, 1);
    const InterfaceState& sa = a->world().interfaceState(0);
    const InterfaceState& sb = b->world().interfaceState(0);
    ASSERT_EQ(sa.proxy_position, sb.proxy_position) << "tick " << k;
    ASSERT_EQ(sa.user_force, sb.user_force) << "tick " << k;
    ASSERT_EQ(a->world().bodyState(rollSetup().object).pose.matrix(),
              b->world().bodyState(rollSetup().object).pose.matrix())
        << "tick " << k;
    ASSERT_FALSE(sb.oriented);
    ASSERT_EQ(fake_device->lastTorque(), Eigen::Vector3d::Zero()) << "tick " << k;
  }
  // The compared trajectory presses the box (measured 3.33 N through the fake handle).
  EXPECT_GT(b->world().interfaceState(0).user_force.z(), 2.0);
  EXPECT_EQ(b->world().interfaceState(0).contact_count, 1);
  EXPECT_EQ(b->counters().rejected_orientations.load(), 0);
}

// The fake device's script rolls the finger 40 degrees on the box: through the loop, the proxy
// rolls and the contact area's centre moves by fingertip_radius x the angle (8 mm x 0.698 rad =
// 5.59 mm), as in the offline scenario.
TEST(OrientedServo, AnOrientedFakeScriptRollsTheFingerAndTheAreaMoves)
{
  auto loop = makeLoop(rollingHand(), DeviceProfile());
  const int box = rollSetup().object;
  run(*loop, 0, ticksOf(0.8));
  const InterfaceState before = loop->world().interfaceState(0);
  ASSERT_TRUE(before.oriented);
  ASSERT_EQ(before.contact_count, 1);
  ASSERT_EQ(before.contacts[0].body, box);
  run(*loop, ticksOf(0.8), ticksOf(1.7));
  const InterfaceState after = loop->world().interfaceState(0);
  ASSERT_EQ(after.contact_count, 1);
  const double rolled = before.proxy_orientation.angularDistance(after.proxy_orientation);
  EXPECT_NEAR(rolled, kRoll, 1e-3);
  const double travel = (after.contacts[0].point - before.contacts[0].point).norm();
  EXPECT_NEAR(travel, rollParams().finger.fingertip_radius * kRoll, 1e-4) << "travel " << travel;
  RecordProperty("measured", "oriented servo: area moved " + std::to_string(travel) + " m (R_f theta " +
                                 std::to_string(rollParams().finger.fingertip_radius * kRoll) + "), rolled " +
                                 std::to_string(rolled) + " rad");
  // Across the finger (y), the way the pulp turned; not along it.
  EXPECT_LT(std::abs(after.contacts[0].point.x() - before.contacts[0].point.x()), 1e-4);
}

// The torque goes to the device on the profile's axes only, in the device frame, saturated at
// max_torque; a force-only profile sends none; a tick of an oriented finger at rest in contact
// allocates nothing.
TEST(OrientedServo, TheTorqueReachesTheDeviceOnTheProfilesAxesOnly)
{
  // The device frame turned 90 degrees about z from the world: the world's x (the roll's axis)
  // is the device's -y.
  WorkspaceMappingParams turned;
  turned.rotation = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ());
  // The script is in the world: turn it into the device frame.
  const ScenarioSetup setup = rollSetup();
  std::vector<Waypoint> path = setup.fingers[0].waypoints();
  for (Waypoint& waypoint : path)
  {
    waypoint.position = turned.rotation.inverse() * waypoint.position;
  }
  std::vector<OrientationWaypoint> turns;
  for (double t : {0.0, 0.8, 1.8, 2.5})
  {
    turns.push_back({t, turned.rotation.inverse() * setup.orientations[0].at(t)});
  }
  DeviceProfile profile;
  profile.torque_axes = kTorqueY | kTorqueZ;
  profile.max_torque = 1.0;
  auto device = std::make_unique<FakeDevice>(FakeDeviceParams(), WaypointPath(path), OrientationPath(turns));
  device->setScriptStart(0.0);
  FakeDevice* fake = device.get();
  auto loop = makeLoop(std::move(device), profile, WorkspaceMapping(turned));
  Eigen::Vector3d commanded = Eigen::Vector3d::Zero();
  double peak = 0.0;  // N m, the largest device torque during the roll
  // N m, world: the extremes of the torque on the hand about the roll's axis as the roll starts
  // (0.8 s to 1 s): the proxy lags the device, so the hand is pulled back (-x) first.
  double start_min = 0.0;
  double start_max = 0.0;
  double tilt_capacity = 0.0;  // N m: N a, the pad's tilt rows' bound, the largest during the roll
  run(*loop, 0, ticksOf(0.8));
  for (long k = ticksOf(0.8); k < ticksOf(1.8); ++k)
  {
    run(*loop, k, 1, [&commanded](const ServoSample& sample) { commanded = sample.commanded_torque; });
    const Eigen::Vector3d on_hand = loop->world().interfaceState(0).user_torque;  // world
    // What the device got this tick is what was decided for the reading before.
    ASSERT_EQ(fake->lastTorque().x(), 0.0) << "tick " << k;  // not one of the profile's axes
    // The world's x is the device's -y: the torque on the hand's roll axis, mapped.
    ASSERT_NEAR(commanded.y(), -on_hand.x(), 1e-15) << "tick " << k;
    peak = std::max(peak, std::abs(fake->lastTorque().y()));
    const InterfaceState& finger = loop->world().interfaceState(0);
    if (finger.contact_count > 0)
    {
      tilt_capacity =
          std::max(tilt_capacity, finger.user_force.dot(finger.contacts[0].normal) * finger.contacts[0].radius);
    }
    if (k < ticksOf(1.0))
    {
      start_min = std::min(start_min, on_hand.x());
      start_max = std::max(start_max, on_hand.x());
    }
  }
  // Held after the roll: the torque path of a tick allocates nothing.
  run(*loop, ticksOf(1.8), ticksOf(0.2));
  const long allocations = test::allocationCount();
  for (long k = ticksOf(2.0); k < ticksOf(2.1); ++k)
  {
    loop->tick(static_cast<double>(k) * loop->period());  // the samples popped after: that copy allocates
  }
  EXPECT_EQ(test::allocationCount(), allocations);
  EXPECT_NE(fake->lastTorque().y(), 0.0);  // still sending a torque
  // The pad resists the roll at its tilt rows' bound, N a (physics/solver/pad_state.h: the pulp
  // rolls on the box at the pad's tilt capacity), and the hand feels it (measured 0.033 N m; the
  // spring's lag alone gave 1.4e-4 N m before the pad turned with the finger).
  EXPECT_GT(peak, 0.5 * tilt_capacity);
  EXPECT_LT(peak, 1.05 * tilt_capacity);
  // It resists the roll: against it first, the underdamped spring's overshoot (damping ratio
  // 0.45: about 20 %) the other way after.
  EXPECT_LT(start_min, -5e-5);
  EXPECT_LT(start_max, -0.5 * start_min);
  RecordProperty("measured", "oriented servo: device torque peak " + std::to_string(peak) +
                                 " N m during the roll; on the hand at its start " + std::to_string(start_min) +
                                 " to " + std::to_string(start_max) + " N m about x");

  // Saturated at max_torque: a limit under the peak holds it there.
  profile.max_torque = 0.25 * peak;
  auto limited_device = rollingHand();
  FakeDevice* limited = limited_device.get();
  profile.torque_axes = kTorqueX;
  auto limited_loop = makeLoop(std::move(limited_device), profile);
  double limited_peak = 0.0;
  for (long k = 0; k < ticksOf(1.8); ++k)
  {
    run(*limited_loop, k, 1);
    limited_peak = std::max(limited_peak, limited->lastTorque().norm());
    ASSERT_EQ(limited->lastTorque().y(), 0.0);
    ASSERT_EQ(limited->lastTorque().z(), 0.0);
  }
  EXPECT_NEAR(limited_peak, profile.max_torque, 1e-12 * peak);

  // A force-only profile (the Omni's, the Falcon's): the same roll sends no torque.
  auto force_only_device = rollingHand();
  FakeDevice* force_only = force_only_device.get();
  auto force_only_loop = makeLoop(std::move(force_only_device), DeviceProfile());
  for (long k = 0; k < ticksOf(1.8); ++k)
  {
    run(*force_only_loop, k, 1);
    ASSERT_EQ(force_only->lastTorque(), Eigen::Vector3d::Zero()) << "tick " << k;
  }
  EXPECT_GT(force_only_loop->world().interfaceState(0).user_torque.norm(), 0.0);  // there was one to send
}

// The torque goes through the force's guard (ForceGuard::scale): while the force is stopped
// (kStopForce) the device gets no torque; resumed (kResumeForce), the torque ramps in with the
// force's soft start: each tick's torque is softStartScale(t - t_resume, soft_start) times the
// torque decided for it, on the force's clock.
TEST(OrientedServo, TheTorqueStopsAndRampsInWithTheForce)
{
  DeviceProfile profile;
  profile.torque_axes = kTorqueX;
  profile.max_torque = 1.0;
  const double soft_start = profile.guard.soft_start;  // 0.5 s
  auto device = rollingHand();
  FakeDevice* fake = device.get();
  auto loop = makeLoop(std::move(device), profile);
  run(*loop, 0, ticksOf(1.0));
  ASSERT_NE(fake->lastTorque().x(), 0.0);
  ServoCommand stop;
  stop.kind = ServoCommand::Kind::kStopForce;
  ASSERT_TRUE(loop->post(stop));
  for (long k = ticksOf(1.0); k < ticksOf(1.2); ++k)
  {
    run(*loop, k, 1);
    if (k > ticksOf(1.0))
    {
      ASSERT_EQ(fake->lastTorque(), Eigen::Vector3d::Zero()) << "tick " << k;
    }
  }
  // Resumed at 1.2 s (the command is taken at the end of that tick): mid-roll, a torque to send.
  ServoCommand resume;
  resume.kind = ServoCommand::Kind::kResumeForce;
  ASSERT_TRUE(loop->post(resume));
  const double resumed = static_cast<double>(ticksOf(1.2)) * loop->period();
  std::vector<Eigen::Vector3d> decided(ticksOf(2.0), Eigen::Vector3d::Zero());  // by sample tick
  std::vector<Eigen::Vector3d> applied(ticksOf(2.0), Eigen::Vector3d::Zero());  // the samples' applied_torque
  std::vector<Eigen::Vector3d> given(ticksOf(2.0), Eigen::Vector3d::Zero());    // what the device got, by tick
  long compared = 0;
  double at_quarter = NAN;  // the scale 0.125 s after the resume
  for (long k = ticksOf(1.2); k < ticksOf(1.8); ++k)
  {
    run(*loop, k, 1,
        [&decided, &applied](const ServoSample& sample)
        {
          if (sample.tick >= 0 && sample.tick < static_cast<long>(decided.size()))
          {
            decided[sample.tick] = sample.commanded_torque;
            applied[sample.tick] = sample.applied_torque;
          }
        });
    given[k] = fake->lastTorque();
    if (k == ticksOf(1.2))
    {
      ASSERT_EQ(fake->lastTorque(), Eigen::Vector3d::Zero());  // read before the resume was taken
      continue;
    }
    const double t = static_cast<double>(k) * loop->period();
    const double scale = softStartScale(t - resumed, soft_start);
    // What the device got this tick: the torque decided at the tick before, scaled.
    ASSERT_NEAR(fake->lastTorque().x(), scale * decided[k - 1].x(), 1e-15) << "tick " << k;
    ASSERT_LE(std::abs(fake->lastTorque().x()), std::abs(decided[k - 1].x())) << "tick " << k;
    if (decided[k - 1].x() != 0.0)
    {
      ++compared;
    }
    if (k == ticksOf(1.325))
    {
      at_quarter = fake->lastTorque().x() / decided[k - 1].x();
    }
  }
  // The samples (device/state's applied_torque) carry what the device got at their tick.
  for (long k = ticksOf(1.2); k < ticksOf(1.79); ++k)
  {
    ASSERT_EQ(applied[k], given[k]) << "tick " << k;
  }
  EXPECT_GT(compared, ticksOf(0.5));  // a torque to scale on nearly every tick
  EXPECT_NEAR(at_quarter, 0.25, 1e-9);
  RecordProperty("measured", "torque 0.125 s after resume: " + std::to_string(at_quarter) + " of the decided torque");
}

// The interactive hand through the loop (kHandTarget, as hand_marker.h posts it): dragged by
// position only the finger stays 3-DOF; once the marker is turned (hand_oriented) the finger is
// oriented, and rolling the marker 40 degrees about the finger's axis in 2-degree mouse steps
// moves the area across the box by fingertip_radius x 40 degrees.
TEST(OrientedServo, TheInteractiveHandOrientsTheFingerOnlyOnceTurned)
{
  auto loop = makeLoop(rollingHand(false), DeviceProfile());
  const Eigen::Vector3d pressing(0.002, 0.0, 0.053);  // roll_finger's pressing hand (device = world)
  ServoCommand drag;
  drag.kind = ServoCommand::Kind::kHandTarget;
  drag.hand_target = pressing;
  run(*loop, 0, ticksOf(0.3));
  ASSERT_TRUE(loop->post(drag));
  run(*loop, ticksOf(0.3), ticksOf(0.4));
  const InterfaceState dragged = loop->world().interfaceState(0);
  EXPECT_FALSE(dragged.oriented);
  ASSERT_EQ(dragged.contact_count, 1);
  // The marker's first turn: at rest (identity) it is the finger pulp down (hand_marker.h
  // fingerOrientationOfMarker: 180 degrees about x); the roll turns it about x.
  drag.hand_oriented = true;
  drag.hand_orientation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()));
  ASSERT_TRUE(loop->post(drag));
  run(*loop, ticksOf(0.7), ticksOf(0.1));
  const InterfaceState before = loop->world().interfaceState(0);
  ASSERT_TRUE(before.oriented);
  ASSERT_EQ(before.contact_count, 1);
  long k = ticksOf(0.8);
  for (int step = 1; step <= 20; ++step, k += ticksOf(0.02))
  {
    drag.hand_orientation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI + step * kRoll / 20.0, Eigen::Vector3d::UnitX()));
    ASSERT_TRUE(loop->post(drag));
    run(*loop, k, ticksOf(0.02));
  }
  run(*loop, k, ticksOf(0.3));
  const InterfaceState after = loop->world().interfaceState(0);
  ASSERT_EQ(after.contact_count, 1);
  const double rolled = before.proxy_orientation.angularDistance(after.proxy_orientation);
  EXPECT_NEAR(rolled, kRoll, 1e-3);
  const double travel = (after.contacts[0].point - before.contacts[0].point).norm();
  EXPECT_NEAR(travel, rollParams().finger.fingertip_radius * kRoll, 1e-4) << "travel " << travel;
  EXPECT_LT(std::abs(after.contacts[0].point.x() - before.contacts[0].point.x()), 1e-4);
  RecordProperty("measured", "interactive roll: area moved " + std::to_string(travel) + " m, rolled " +
                                 std::to_string(rolled) + " rad");
}

// NaN, zero-norm and far-from-unit quaternions from a device are ignored and counted: the finger
// keeps its last good orientation (none yet: it stays 3-DOF), nothing non-finite reaches the
// physics or the samples, and the position is still followed.
TEST(OrientedServo, UnusableOrientationsAreIgnoredCountedAndNeverReachThePhysics)
{
  const Eigen::Quaterniond good(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()));
  const Eigen::Quaterniond turned(Eigen::AngleAxisd(M_PI + 0.3, Eigen::Vector3d::UnitX()));
  auto device = std::make_unique<TurningDevice>();
  device->orientation = [&](double t) -> Eigen::Quaterniond
  {
    if (t < 0.05)
    {
      return Eigen::Quaterniond(NAN, 0.0, 0.0, 0.0);  // before any good one
    }
    if (t < 0.1)
    {
      return good;
    }
    if (t < 0.2)
    {
      return Eigen::Quaterniond(NAN, 1.0, 0.0, 0.0);
    }
    if (t < 0.3)
    {
      return Eigen::Quaterniond(0.0, 0.0, 0.0, 0.0);
    }
    if (t < 0.4)
    {
      return Eigen::Quaterniond(0.0, 3.0, 0.0, 0.0);  // norm 3
    }
    return turned;
  };
  auto loop = makeLoop(std::move(device), DeviceProfile());
  run(*loop, 0, ticksOf(0.05));
  EXPECT_FALSE(loop->world().interfaceState(0).oriented);  // no good orientation yet: 3-DOF
  EXPECT_EQ(loop->counters().rejected_orientations.load(), ticksOf(0.05));
  const long rejected_targets = loop->world().counters().rejected_targets;
  for (long k = ticksOf(0.05); k < ticksOf(0.6); ++k)
  {
    run(*loop, k, 1,
        [](const ServoSample& sample)
        {
          ASSERT_TRUE(sample.reading.orientation.coeffs().allFinite());
          ASSERT_TRUE(sample.user_torque.allFinite());
        });
    const InterfaceState& state = loop->world().interfaceState(0);
    ASSERT_TRUE(state.proxy_orientation.coeffs().allFinite()) << "tick " << k;
    ASSERT_TRUE(state.user_torque.allFinite()) << "tick " << k;
    if (k >= ticksOf(0.1) && k < ticksOf(0.4))
    {
      // The last good one stays.
      ASSERT_LT(state.interface_orientation.angularDistance(good), 1e-12) << "tick " << k;
    }
  }
  EXPECT_EQ(loop->counters().rejected_orientations.load(), ticksOf(0.05) + ticksOf(0.3));
  EXPECT_EQ(loop->world().counters().rejected_targets, rejected_targets);  // the loop passed on none
  EXPECT_EQ(loop->counters().rejected_readings.load(), 0);                 // the positions were taken
  EXPECT_LT(loop->world().interfaceState(0).proxy_orientation.angularDistance(turned), 1e-3);
}
}  // namespace
}  // namespace god_finger
