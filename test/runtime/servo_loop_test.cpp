// The servo loop without ROS: deterministic on simulated time, the hand feels the reaction of
// the force that pulls the proxy (one coupling, the device's profile), commands and buttons
// are applied between two steps, bad readings and failing devices are contained, and a tick
// allocates nothing.
#include "god_finger/runtime/servo_loop.h"
#include "allocation_counter.h"
#include "device_profile_file.h"
#include "god_finger/devices/fake_device.h"
#include "god_finger/runtime/servo_clock.h"
#include "god_finger/scene/scene_file.h"
#include "god_finger/scene/urdf_scene.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <future>
#include <new>

namespace god_finger
{
namespace
{
const std::string kScene = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes/table_sphere.urdf";

// A scripted device for the edge cases: positions from a function of time, buttons, faults.
class ScriptedDevice : public HapticDevice
{
 public:
  std::function<Eigen::Vector3d(double)> position = [](double) { return Eigen::Vector3d(0, 0, 0.1); };
  std::function<std::uint32_t(double)> buttons = [](double) { return 0u; };
  double fail_at = INFINITY;
  Eigen::Vector3d last_force = Eigen::Vector3d::Zero();
  std::string name() const override
  {
    return "scripted";
  }
  void start() override {}
  DeviceReading update(double time, const Eigen::Vector3d& force) override
  {
    if (time >= fail_at)
    {
      throw DeviceError("scripted: unplugged");
    }
    last_force = force;
    DeviceReading reading;
    reading.position = position(time);
    reading.buttons = buttons(time);
    return reading;
  }
};

// The press_sphere script: the hand comes down on the ball's top and stays.
std::unique_ptr<HapticDevice> pressingHand()
{
  auto device = std::make_unique<FakeDevice>(
      FakeDeviceParams(), WaypointPath({{0.0, Eigen::Vector3d(0, 0, 0.1)}, {0.5, Eigen::Vector3d(0.002, 0, 0.075)}}));
  device->setScriptStart(0.0);
  return device;
}

std::unique_ptr<ServoLoop> makeLoop(std::unique_ptr<HapticDevice> device, const DeviceProfile& profile = {},
                                    ContactModel model = ContactModel::kGodFinger)
{
  WorldParams world;
  world.model = model;
  world.contact.distance_constant = 0.001;
  std::vector<ServoInterface> interfaces(1);
  interfaces[0].name = "finger";
  interfaces[0].device = std::move(device);
  interfaces[0].profile = profile;
  ServoLoopParams params;
  params.simulated_time = true;
  params.real_time_factor = 0.0;
  auto loop = std::make_unique<ServoLoop>(std::make_unique<GodFingerWorld>(loadUrdfScene(kScene), world),
                                          std::move(interfaces), params);
  loop->prepare();
  return loop;
}

void runTicks(ServoLoop& loop, int ticks, int first = 0)
{
  for (int k = first; k < first + ticks; ++k)
  {
    loop.tick(k * loop.period());
  }
}

void drain(ServoLoop& loop)
{
  ServoSample sample;
  while (loop.samples().tryPop(&sample))
  {
  }
  WorldSnapshot snapshot;
  while (loop.snapshots().tryPop(&snapshot))
  {
  }
}

// Issue 18: a hand that starts inside the table or the ball (a workspace offset too low) stops
// the loop before it starts, naming the interface, the body and the position; no proxy is made.
TEST(ServoLoop, AHandThatStartsInsideABodyIsRefusedWithTheBodyNamed)
{
  const std::pair<Eigen::Vector3d, std::string> cases[] = {
      {Eigen::Vector3d(0.2, 0.0, -0.02), "table"},  // the table's top is z = 0, 4 cm thick
      {Eigen::Vector3d(0.0, 0.0, 0.04), "ball"},    // the ball's centre
  };
  for (const auto& [start, body] : cases)
  {
    auto device = std::make_unique<ScriptedDevice>();
    device->position = [start = start](double) { return start; };
    try
    {
      makeLoop(std::move(device));
      ADD_FAILURE() << "a proxy inside the " << body;
    }
    catch (const InputError& error)
    {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind("interface 'finger': interface 0 would start inside body '" + body + "'", 0), 0u)
          << message;
      EXPECT_NE(message.find("workspace_offset"), std::string::npos) << message;
    }
  }
}

TEST(ServoLoop, SimulatedTimeGivesTheSameTrajectoryBitForBit)
{
  auto a = makeLoop(pressingHand());
  auto b = makeLoop(pressingHand());
  for (int k = 0; k < 1500; ++k)
  {
    a->tick(k * a->period());
    b->tick(k * b->period());
    drain(*a);
    drain(*b);
    const BodyState ball_a = a->world().bodyState(1);
    const BodyState ball_b = b->world().bodyState(1);
    ASSERT_EQ(ball_a.pose.matrix(), ball_b.pose.matrix()) << "tick " << k;
    ASSERT_EQ(a->world().interfaceState(0).user_force, b->world().interfaceState(0).user_force) << "tick " << k;
  }
  // The hand did press the ball: the trajectory compared is not a resting one.
  EXPECT_GT(a->world().interfaceState(0).user_force.z(), 1.0);
  EXPECT_EQ(a->world().interfaceState(0).contact_count, 1);
}

TEST(ServoLoop, TheHandFeelsTheReactionOfTheForceThatPullsTheProxy)
{
  // config/devices/falcon.yaml's coupling and force limit, not the world's default.
  DeviceProfile falcon = test::shippedDeviceProfile("falcon");
  // The fake hand's script lies in the fake device's workspace (z up to 0.1 m), not in the
  // Falcon's 5 cm: the case is about the coupling, so the Falcon's wall stays out of it.
  falcon.workspace_radius = test::shippedDeviceProfile("fake").workspace_radius;
  const double k = falcon.coupling.stiffness;
  const double max_force = falcon.coupling.max_force;
  ASSERT_NE(k, WorldParams().coupling.stiffness) << "the case would not show which coupling the loop uses";
  auto loop = makeLoop(pressingHand(), falcon);
  EXPECT_EQ(loop->world().coupling(0).stiffness, k);
  EXPECT_EQ(loop->world().coupling(0).damping, falcon.coupling.damping);
  EXPECT_EQ(loop->world().coupling(0).max_force, falcon.coupling.max_force);
  runTicks(*loop, 1200);
  ServoSample sample;
  int checked = 0;
  while (loop->samples().tryPop(&sample))
  {
    // Device frame = world here (identity mapping): the command is the user force, guarded.
    const Eigen::Vector3d expected = sample.user_force.norm() > max_force
                                         ? Eigen::Vector3d(sample.user_force.normalized() * max_force)
                                         : sample.user_force;
    ASSERT_LT((sample.commanded_force - expected).norm(), 1e-12) << "tick " << sample.tick;
    ++checked;
  }
  EXPECT_EQ(checked, 1200);
  // Resting on the ball, the spring the hand feels is the profile's: force = k (p_GO - p_I).
  const InterfaceState& state = loop->world().interfaceState(0);
  const Eigen::Vector3d spring = k * (state.proxy_position - state.interface_position);
  EXPECT_NEAR(state.user_force.z(), spring.z(), 0.01 * std::abs(spring.z()));
  EXPECT_GT(state.user_force.z(), 1.0);
}

TEST(ServoLoop, CommandsAreAppliedBetweenTwoSteps)
{
  auto loop = makeLoop(pressingHand());
  runTicks(*loop, 10);
  ServoCommand command;
  command.kind = ServoCommand::Kind::kSetContactModel;
  command.model = ContactModel::kSoftFinger;
  ASSERT_TRUE(loop->post(command));
  EXPECT_EQ(loop->world().contactModel(), ContactModel::kGodFinger);  // not before the next tick
  runTicks(*loop, 1, 10);
  EXPECT_EQ(loop->world().contactModel(), ContactModel::kSoftFinger);
  EXPECT_EQ(static_cast<ContactModel>(loop->counters().model.load()), ContactModel::kSoftFinger);

  ServoCommand bad;
  bad.kind = ServoCommand::Kind::kSetContactParams;
  bad.contact.alpha = 0.5;
  std::string error;
  EXPECT_FALSE(loop->post(bad, &error));
  EXPECT_EQ(error, "parameter 'alpha' = 0.5 is out of range [1, 100] (dimensionless)");

  ServoCommand params;
  params.kind = ServoCommand::Kind::kSetContactParams;
  params.contact.max_radius = 0.004;
  ASSERT_TRUE(loop->post(params));
  runTicks(*loop, 1, 11);
  EXPECT_EQ(loop->world().params().contact.max_radius, 0.004);

  runTicks(*loop, 800, 12);
  ServoCommand reset;
  reset.kind = ServoCommand::Kind::kReset;
  ASSERT_TRUE(loop->post(reset));
  runTicks(*loop, 1, 812);
  EXPECT_EQ(loop->world().steps(), 1);  // the world restarted, then took this tick's step
  // The proxy restarted where the hand is (pressed 2 mm into the ball, out of which the contact
  // pushes it), not at the start position 2.5 cm away, which gave the hand max_force for a tick.
  EXPECT_LT(loop->world().interfaceState(0).user_force.norm(), 1.0);
  EXPECT_LT(
      (loop->world().interfaceState(0).proxy_position - loop->world().interfaceState(0).interface_position).norm(),
      0.005);
}

// Issue 18: the pad solver changes live, between two steps, like the other parameters; a value
// that names none is refused by post().
TEST(ServoLoop, ThePadSolverChangesBetweenTwoSteps)
{
  auto loop = makeLoop(pressingHand());
  runTicks(*loop, 600);  // pressing the ball
  EXPECT_EQ(loop->world().params().pad_solver, PadSolver::kConstraint);
  const int rows_constraint = loop->world().counters().solver_contact_rows;
  ServoCommand command;
  command.kind = ServoCommand::Kind::kSetPadSolver;
  command.pad_solver = PadSolver::kPoints;
  ASSERT_TRUE(loop->post(command));
  EXPECT_EQ(loop->world().params().pad_solver, PadSolver::kConstraint);  // not before the next tick
  runTicks(*loop, 1, 600);
  EXPECT_EQ(loop->world().params().pad_solver, PadSolver::kPoints);
  EXPECT_EQ(static_cast<PadSolver>(loop->counters().pad_solver.load()), PadSolver::kPoints);
  runTicks(*loop, 100, 601);
  // The paper's points: a row set per sub-god-object, more than the pad's rows.
  EXPECT_GT(loop->world().counters().solver_contact_rows, rows_constraint);
  EXPECT_LT(loop->world().interfaceState(0).user_force.norm(), 20.0);
  EXPECT_TRUE(loop->world().interfaceState(0).proxy_position.allFinite());

  ServoCommand bad;
  bad.kind = ServoCommand::Kind::kSetPadSolver;
  bad.pad_solver = static_cast<PadSolver>(7);
  std::string error;
  EXPECT_FALSE(loop->post(bad, &error));
  EXPECT_EQ(error, "pad solver 7 is not one of points, constraint");
}

TEST(ServoLoop, ButtonZeroCyclesTheModelAndButtonOneResets)
{
  auto device = std::make_unique<ScriptedDevice>();
  device->buttons = [](double t) { return (t >= 0.0095 && t < 0.0205) ? 1u : (t >= 0.0495 && t < 0.06) ? 2u : 0u; };
  auto loop = makeLoop(std::move(device), DeviceProfile(), ContactModel::kGodObject);
  runTicks(*loop, 30);
  EXPECT_EQ(loop->world().contactModel(), ContactModel::kGodFinger);  // one press: one step along the list
  runTicks(*loop, 30, 30);
  EXPECT_EQ(loop->world().steps(), 10);  // reset at tick 50 (whose step is the first), ticks 51-59
}

// Issue 18: time never goes backwards. A reset (the command, or button 1) sends the world's time
// to 0 while the loop's clock (/clock on simulated time) goes on: the snapshots' time, which
// stamps TF, markers and contact areas, stays on the loop's clock; before any reset it is the
// world's own time.
TEST(ServoLoop, SnapshotTimeNeverGoesBackAcrossAReset)
{
  auto device = std::make_unique<ScriptedDevice>();
  device->buttons = [](double t) { return (t >= 0.1995 && t < 0.2005) ? 2u : 0u; };  // button 1 at tick 200
  auto loop = makeLoop(std::move(device));
  std::vector<double> times;
  ServoSample sample;
  WorldSnapshot snapshot;
  for (int k = 0; k < 300; ++k)
  {
    if (k == 100)
    {
      ServoCommand reset;
      reset.kind = ServoCommand::Kind::kReset;
      ASSERT_TRUE(loop->post(reset));
    }
    loop->tick(k * loop->period());
    while (loop->samples().tryPop(&sample))
    {
    }
    while (loop->snapshots().tryPop(&snapshot))
    {
      if (k < 100)
      {
        EXPECT_EQ(snapshot.time, loop->world().time()) << "tick " << k;  // unchanged before a reset
      }
      times.push_back(snapshot.time);
    }
  }
  ASSERT_GE(times.size(), 3u);
  for (std::size_t i = 1; i < times.size(); ++i)
  {
    ASSERT_GT(times[i], times[i - 1]) << "snapshot " << i;
  }
  EXPECT_NEAR(loop->world().time(), 0.1, 1e-9);           // the button's reset at tick 200, 100 steps since
  EXPECT_NEAR(times.back(), 289 * loop->period(), 1e-9);  // the last snapshot: tick 288, after its step
}

TEST(ServoLoop, NonFiniteReadingsAreRejectedAndTheLastTargetStays)
{
  auto device = std::make_unique<ScriptedDevice>();
  device->position = [](double t) { return t >= 0.05 ? Eigen::Vector3d(NAN, 0, 0.1) : Eigen::Vector3d(0, 0, 0.1); };
  auto loop = makeLoop(std::move(device));
  runTicks(*loop, 100);
  EXPECT_EQ(loop->counters().rejected_readings.load(), 50);
  // Counted once, by the loop: the world gets the last good target.
  EXPECT_EQ(loop->world().counters().rejected_targets, 0);
  EXPECT_TRUE(loop->world().interfaceState(0).interface_position.isApprox(Eigen::Vector3d(0, 0, 0.1)));
  EXPECT_TRUE(loop->world().interfaceState(0).user_force.allFinite());
}

// The servo topology's device/state is published from the samples: a non-finite reading
// is never passed on (the sample carries the last good one), and its buttons press nothing.
TEST(ServoLoop, NonFiniteReadingsAreNeverPassedOnAndTheirButtonsPressNothing)
{
  auto device = std::make_unique<ScriptedDevice>();
  // Good readings before tick 20 and after tick 60; between, every reading is non-finite (in
  // its position or, from tick 40, its velocity) with button 0 (tick 20-29) then button 1
  // (tick 30-39) pressed.
  device->position = [](double t)
  { return (t >= 0.0195 && t < 0.0395) ? Eigen::Vector3d(0, NAN, 0.1) : Eigen::Vector3d(0, 0, 0.1 - 0.1 * t); };
  device->buttons = [](double t) { return (t >= 0.0195 && t < 0.0295) ? 1u : (t >= 0.0295 && t < 0.0395) ? 2u : 0u; };
  struct InfiniteVelocity : public HapticDevice
  {
    std::unique_ptr<ScriptedDevice> inner;
    std::string name() const override
    {
      return "infinite velocity";
    }
    void start() override {}
    DeviceReading update(double time, const Eigen::Vector3d& force) override
    {
      DeviceReading reading = inner->update(time, force);
      if (time >= 0.0395 && time < 0.0595)
      {
        reading.velocity = Eigen::Vector3d(INFINITY, 0, 0);
        reading.buttons = 3u;
      }
      return reading;
    }
  };
  auto wrapped = std::make_unique<InfiniteVelocity>();
  wrapped->inner = std::move(device);
  auto loop = makeLoop(std::move(wrapped), DeviceProfile(), ContactModel::kGodObject);
  ServoSample sample;
  Eigen::Vector3d last_good = Eigen::Vector3d::Zero();
  int passed_on = 0;
  for (int k = 0; k < 100; ++k)
  {
    loop->tick(k * loop->period());
    while (loop->samples().tryPop(&sample))
    {
      const bool finite = sample.reading.position.allFinite() && sample.reading.velocity.allFinite() &&
                          sample.interface_position.allFinite();
      passed_on += finite ? 0 : 1;
      if (sample.tick >= 20 && sample.tick < 60)
      {
        EXPECT_EQ(sample.reading.position, last_good) << "tick " << sample.tick;
        EXPECT_EQ(sample.reading.buttons, 0u) << "tick " << sample.tick;
      }
      else
      {
        last_good = sample.reading.position;
      }
    }
    WorldSnapshot snapshot;
    while (loop->snapshots().tryPop(&snapshot))
    {
    }
  }
  EXPECT_EQ(passed_on, 0);
  EXPECT_EQ(loop->counters().rejected_readings.load(), 40);
  EXPECT_EQ(loop->world().counters().rejected_targets, 0);
  EXPECT_EQ(loop->world().contactModel(), ContactModel::kGodObject);  // button 0 of a bad reading: no cycle
  EXPECT_EQ(loop->world().steps(), 100);                              // button 1 of a bad reading: no reset
}

TEST(ServoLoop, AFailingDeviceStopsTheLoopAndSaysWhy)
{
  auto device = std::make_unique<ScriptedDevice>();
  device->fail_at = 0.05;
  WorldParams world;
  std::vector<ServoInterface> interfaces(1);
  interfaces[0].name = "finger";
  interfaces[0].device = std::move(device);
  ServoLoopParams params;
  params.simulated_time = true;
  params.real_time_factor = 0.0;
  std::string logged;
  ServoLoop loop(std::make_unique<GodFingerWorld>(loadUrdfScene(kScene), world), std::move(interfaces), params,
                 [&logged](const std::string& message) { logged = message; });
  loop.start();
  for (int i = 0; i < 2000 && loop.running(); ++i)
  {
    drain(loop);
    sleepFor(1e-3);
  }
  EXPECT_FALSE(loop.running());
  EXPECT_TRUE(loop.counters().failed.load());
  EXPECT_EQ(loop.counters().ticks.load(), 50);
  EXPECT_EQ(logged, "servo loop stopped: scripted: unplugged");
}

TEST(ServoLoop, BadParametersAndMismatchedTimeStepsAreRefused)
{
  std::vector<ServoInterface> interfaces(1);
  interfaces[0].device = std::make_unique<ScriptedDevice>();
  ServoLoopParams params;
  params.rate = 500.0;  // the world steps at 1 kHz
  try
  {
    ServoLoop loop(std::make_unique<GodFingerWorld>(loadUrdfScene(kScene), WorldParams()), std::move(interfaces),
                   params);
    FAIL() << "a 500 Hz loop over a 1 ms world was accepted";
  }
  catch (const InputError& error)
  {
    EXPECT_EQ(std::string(error.what()), "the world's time step 0.001 s is not one servo period (1 / 500 Hz)");
  }
  params.rate = 5.0;
  EXPECT_EQ(validate(params), "parameter 'rate' = 5 is out of range [10, 10000] (Hz)");
  DeviceProfile unstable;
  unstable.coupling.stiffness = 90000.0;  // (k dt + 2 b) dt / m = 4.9 with the 20 g proxy
  std::vector<ServoInterface> stiff(1);
  stiff[0].device = std::make_unique<ScriptedDevice>();
  stiff[0].profile = unstable;
  ServoLoopParams ok;
  ServoLoop loop(std::make_unique<GodFingerWorld>(loadUrdfScene(kScene), WorldParams()), std::move(stiff), ok);
  EXPECT_THROW(loop.prepare(), InputError);
}

// Issue 53: a spawn or a delete is the physics side's. Applied between two steps, it changes the
// world's scene, which other threads read from the snapshots (each with the scene of its step),
// and it is counted with the resets in world_rebuilds: the commands that allocate on the physics
// thread.
TEST(ServoLoop, SpawnsDeletesAndResetsAreThePhysicsSidesAndCounted)
{
  auto device = std::make_unique<ScriptedDevice>();
  device->buttons = [](double t) { return (t >= 0.0495 && t < 0.0505) ? 2u : 0u; };  // button 1 at tick 50
  auto loop = makeLoop(std::move(device));
  runTicks(*loop, 60);
  drain(*loop);
  EXPECT_EQ(loop->counters().world_rebuilds.load(), 1);  // the button's reset
  const std::size_t bodies = loop->world().scene().bodies.size();
  ObjectPlacement placement;
  placement.name = "block";
  placement.pose.translation() = Eigen::Vector3d(0.2, 0.0, 0.05);
  ServoCommand spawn;
  spawn.kind = ServoCommand::Kind::kAddObject;
  spawn.edit = std::make_shared<ObjectEdit>();
  spawn.edit->object = GodFingerWorld::prepareObject(
      loadPlacedObject(std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/objects/block.urdf", placement),
      loop->world().params());
  std::future<ObjectEdit::Outcome> spawned = spawn.edit->done.get_future();
  ASSERT_TRUE(loop->post(spawn));
  EXPECT_EQ(loop->world().scene().bodies.size(), bodies);  // not before the next tick
  runTicks(*loop, 20, 60);                                 // a snapshot at tick 64
  ASSERT_EQ(spawned.wait_for(std::chrono::seconds(0)), std::future_status::ready);
  EXPECT_TRUE(spawned.get().success);
  EXPECT_EQ(loop->world().scene().bodies.size(), bodies + 1);
  WorldSnapshot snapshot;
  bool snapshots = false;
  while (loop->snapshots().tryPop(&snapshot))
  {
    snapshots = true;
    EXPECT_EQ(snapshot.scene->bodies.size(), bodies + 1);
    EXPECT_EQ(snapshot.bodies.size(), bodies + 1);
  }
  EXPECT_TRUE(snapshots);
  ServoCommand remove;
  remove.kind = ServoCommand::Kind::kRemoveObject;
  remove.edit = std::make_shared<ObjectEdit>();
  remove.edit->name = "block";
  std::future<ObjectEdit::Outcome> removed = remove.edit->done.get_future();
  ASSERT_TRUE(loop->post(remove));
  runTicks(*loop, 1, 80);
  ASSERT_EQ(removed.wait_for(std::chrono::seconds(0)), std::future_status::ready);
  EXPECT_TRUE(removed.get().success);
  EXPECT_EQ(loop->world().scene().bodies.size(), bodies);
  EXPECT_EQ(loop->counters().world_rebuilds.load(), 3);
  drain(*loop);
}

TEST(ServoLoop, ATickAllocatesNothing)
{
  auto loop = makeLoop(pressingHand());
  runTicks(*loop, 800);  // in contact: contact areas, injected sub-god-objects, warm starts
  drain(*loop);
  const long before = test::allocationCount();
  runTicks(*loop, 100, 800);
  const long during = test::allocationCount() - before;
  drain(*loop);
  EXPECT_EQ(during, 0);
  EXPECT_EQ(loop->world().interfaceState(0).contact_count, 1);
}

TEST(ServoLoop, RealTimeThreadRunsNeverAheadOfItsSchedule)
{
  // Rates, periods and latencies are measured in scripts/bench. Here only what a loaded machine
  // cannot break: the loop runs on the wall clock (a loose floor: 500 ticks within 10 s, a
  // twentieth of its rate), never ahead of its schedule (tick k starts no earlier than k
  // periods after the loop started: at most elapsed / period + 1 ticks), and every tick leaves
  // a sample or counts a dropped one.
  std::vector<ServoInterface> interfaces(1);
  interfaces[0].device = pressingHand();
  ServoLoop loop(std::make_unique<GodFingerWorld>(loadUrdfScene(kScene), WorldParams()), std::move(interfaces),
                 ServoLoopParams());
  const double start = steadySeconds();
  loop.start();
  long samples = 0;
  ServoSample sample;
  while (loop.counters().ticks.load() < 500 && steadySeconds() - start < 10.0)
  {
    while (loop.samples().tryPop(&sample))
    {
      ++samples;
    }
    sleepFor(2e-3);  // polls the samples queue (a tick's sample is dropped when it is full)
  }
  loop.stop();
  const double elapsed = steadySeconds() - start;
  while (loop.samples().tryPop(&sample))
  {
    ++samples;
  }
  const long ticks = loop.counters().ticks.load();
  std::printf("[ measured ] real-time servo loop: %ld ticks in %.3f s, %ld overruns, %s\n", ticks, elapsed,
              loop.counters().overruns.load(), loop.counters().realtime ? "SCHED_FIFO" : "normal scheduling");
  EXPECT_GE(ticks, 500) << "the loop ran " << ticks << " ticks in " << elapsed << " s";
  EXPECT_LE(ticks, elapsed / loop.period() + 1.001) << "the loop ran ahead of its schedule";  // + rounding
  EXPECT_EQ(samples + loop.counters().dropped_samples.load(), ticks);
}

// Issue 18: a reading twice the workspace radius away is clamped onto the workspace for the
// world (the proxy stays inside) and the hand feels a wall pushing it back in.
TEST(ServoLoop, AReadingOutsideTheWorkspaceIsClampedAndPushedBack)
{
  DeviceProfile profile;
  profile.workspace_radius = 0.1;  // m; the hand at 0.2 m, straight up, over free space
  auto device = std::make_unique<ScriptedDevice>();
  device->position = [](double) { return Eigen::Vector3d(0, 0, 0.2); };
  ScriptedDevice* hand = device.get();
  auto loop = makeLoop(std::move(device), profile);
  runTicks(*loop, 700);  // past the soft start (0.5 s)
  ServoSample sample;
  ServoSample last;
  while (loop->samples().tryPop(&sample))
  {
    ASSERT_LE(sample.interface_position.norm(), 0.1 + 1e-12) << "tick " << sample.tick;
    ASSERT_LE(sample.proxy_position.norm(), 0.1 + 1e-3) << "tick " << sample.tick;
    last = sample;
  }
  EXPECT_TRUE(last.interface_position.isApprox(Eigen::Vector3d(0, 0, 0.1)));
  // The wall: k_c (0.2 - 0.1) = 40 N down, saturated to max_force; the proxy exerts nothing.
  const double max_force = profile.coupling.max_force;
  EXPECT_NEAR(last.commanded_force.z(), -max_force, 1e-9);
  EXPECT_NEAR(last.commanded_force.head<2>().norm(), 0.0, 1e-9);
  EXPECT_NEAR(hand->last_force.z(), -max_force, 1e-9);  // applied, the soft start over
}

// Issue 18: kStopForce zeroes every device's force at once; kResumeForce brings it back with the
// soft start.
TEST(ServoLoop, StopForceZeroesAndResumeRampsIn)
{
  DeviceProfile profile;
  profile.workspace_radius = 0.1;
  auto device = std::make_unique<ScriptedDevice>();
  device->position = [](double) { return Eigen::Vector3d(0, 0, 0.2); };  // the wall: a constant force
  ScriptedDevice* hand = device.get();
  auto loop = makeLoop(std::move(device), profile);
  const double max_force = profile.coupling.max_force;
  runTicks(*loop, 700);
  EXPECT_NEAR(hand->last_force.z(), -max_force, 1e-9);
  ServoCommand stop;
  stop.kind = ServoCommand::Kind::kStopForce;
  ASSERT_TRUE(loop->post(stop));
  runTicks(*loop, 1, 700);  // the stop is taken at this tick; its force is applied at the next
  for (int k = 701; k < 900; ++k)
  {
    loop->tick(k * loop->period());
    ASSERT_EQ(hand->last_force, Eigen::Vector3d::Zero()) << "tick " << k;
  }
  EXPECT_TRUE(loop->counters().force_stopped);
  ServoCommand resume;
  resume.kind = ServoCommand::Kind::kResumeForce;
  ASSERT_TRUE(loop->post(resume));
  const double resumed = 900 * loop->period();
  for (int k = 900; k < 1500; ++k)
  {
    loop->tick(k * loop->period());
    const double expected = max_force * std::min(1.0, (k * loop->period() - resumed) / profile.guard.soft_start);
    ASSERT_LE(-hand->last_force.z(), expected + 1e-9) << "tick " << k;
    drain(*loop);
  }
  EXPECT_FALSE(loop->counters().force_stopped);
  EXPECT_NEAR(hand->last_force.z(), -max_force, 1e-9);
}

// Button 2 (where the device has one) toggles the stop: zero at once, then the soft start.
TEST(ServoLoop, ButtonTwoStopsAndResumesTheForce)
{
  DeviceProfile profile;
  profile.workspace_radius = 0.1;
  auto device = std::make_unique<ScriptedDevice>();
  device->position = [](double) { return Eigen::Vector3d(0, 0, 0.2); };  // the wall: a constant force
  device->buttons = [](double t) { return (t >= 0.7 && t < 0.72) || (t >= 0.9 && t < 0.92) ? 4u : 0u; };
  ScriptedDevice* hand = device.get();
  auto loop = makeLoop(std::move(device), profile);
  const double max_force = profile.coupling.max_force;
  runTicks(*loop, 700);
  drain(*loop);
  EXPECT_NEAR(hand->last_force.z(), -max_force, 1e-9);
  runTicks(*loop, 2, 700);  // pressed at tick 700; its zero is applied at tick 701
  for (int k = 702; k < 900; ++k)
  {
    loop->tick(k * loop->period());
    ASSERT_EQ(hand->last_force, Eigen::Vector3d::Zero()) << "tick " << k;
  }
  drain(*loop);
  EXPECT_TRUE(loop->counters().force_stopped);
  for (int k = 900; k < 1500; ++k)  // pressed again at tick 900: resumes from there
  {
    loop->tick(k * loop->period());
    const double expected = max_force * std::min(1.0, (k - 900) * loop->period() / profile.guard.soft_start);
    ASSERT_LE(-hand->last_force.z(), expected + 1e-9) << "tick " << k;
    drain(*loop);
  }
  EXPECT_FALSE(loop->counters().force_stopped);
  EXPECT_NEAR(hand->last_force.z(), -max_force, 1e-9);
}
}  // namespace
}  // namespace god_finger
