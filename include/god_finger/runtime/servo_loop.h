// The haptic servo loop: what the hand feels, without ROS (CHAI3D's haptic thread, ros_control's
// real-time/non-real-time split), at two rates: the multi-rate scheme of 6-DOF haptic rendering
// (Ortega, Redon, Coquillart 2007; Knott, Kuhlen 2015). The device's period is sacred, the
// physics' is not. docs/servo_loop.md tells the why; this header is the contract.
//
// Two sides, each owning its state and stating its own contract, that meet only through
// lock-free mailboxes (src/runtime/servo_mailboxes.h: the targets and the step results as
// latest-value triple buffers, and a semaphore that wakes the physics):
//  - the haptic side (src/runtime/haptic_side.h) owns the devices. Every period it gives each
//    device the guarded force for its last reading and reads it, bounds and maps the reading
//    into the world, posts the targets and the buttons' presses (0: next contact model, 1:
//    reset; 2 stops every device's force or resumes it with the soft start), and decides the
//    force for the reading from the last completed step (runtime/multirate_render.h: the step's
//    coupling reaction when on time, bit for bit; when late, the coupling rendered against a
//    predicted proxy, within a force-step bound, watched by the hold's passivity controller).
//    A packet device gets the force for tick k's reading at tick k + 1's update; a frame device
//    (DeviceExchange::kFrame) within the exchange that read it, from the step before.
//  - the physics side (src/runtime/physics_side.h) owns the world. It applies the world
//    commands and the presses, steps with the latest targets (older ones skipped when it is
//    late, their motion carried), and leaves the step's result for the haptic side and, every
//    snapshot_every ticks, a WorldSnapshot for the publishers.
// Oriented fingers: the mapped orientation goes to the physics with the position, and the
// rotational coupling's torque of the last completed step comes back, cut to the profile's axes
// and max_torque, sent with the next force. A finger whose device never reports an orientation
// runs exactly the 3-DOF calls, bit for bit.
//
// Threads and clocks:
//  - real time (CLOCK_MONOTONIC, on runtime/fixed_rate_schedule.h's deadlines: no drift; a late
//    period is an overrun, counted): the haptic side in the loop's thread (SCHED_FIFO
//    realtime_priority), never waiting for the physics; the physics side in its own
//    (realtime_priority - 1; normal scheduling when that is 0), woken by every tick's targets.
//  - simulated time (t = tick / rate exactly; paced at real_time_factor times the wall clock, or
//    as fast as it goes with 0): one thread, in lockstep, the same devices giving the same
//    trajectory bit for bit whatever the load; the loop waits for the publishers instead of
//    dropping their samples. Its test seam, physics_delay (src/runtime/physics_delay_seam.h),
//    makes chosen steps late by whole periods, deterministically.
// Real-time safety: the haptic side (tick() on real time) neither allocates (after prepare())
// nor logs nor takes a lock another thread holds. The physics side allocates only while its
// buffers first grow and to apply a reset, a spawn or a delete (counted in world_rebuilds); the
// haptic thread never waits for it (on simulated time tick() runs it too). On real time the
// loop locks the process's memory when permitted (a warning through the log callback
// otherwise). Other threads: post() (any; producers serialise among themselves, never with the loop), samples() and
// snapshots() (one consumer each), counters(); world() only as its comment says.
//
// Units: s, m, N; device frame for device quantities, world for the rest.
#pragma once

#include "god_finger/devices/haptic_device.h"
#include "god_finger/haptics/device_profile.h"
#include "god_finger/haptics/force_guard.h"
#include "god_finger/haptics/interface_input.h"
#include "god_finger/haptics/workspace_mapping.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/runtime/multirate_render.h"
#include "god_finger/runtime/servo_command.h"
#include "god_finger/support/parameter_table.h"
#include "god_finger/support/spsc_queue.h"

#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace god_finger
{
// One finger: a one-finger device, or one of a hand's fingers (HapticDevice::fingers(); the
// loop runs every finger of every device in one tick).
struct ServoInterface
{
  std::string name;
  std::unique_ptr<HapticDevice> device;
  DeviceProfile profile;
  WorkspaceMapping mapping;
};

struct ServoLoopParams
{
  double rate = 1.0 / WorldParams().time_step;  // Hz: the device rate; the world's step is 1 / rate
  int realtime_priority = 80;                   // SCHED_FIFO priority of the loop thread, 0 for none
  bool lock_memory = true;                      // mlockall when permitted
  bool simulated_time = false;                  // see above
  double real_time_factor = 1.0;                // simulated time only; 0: as fast as it goes
  int snapshot_every = 16;                      // ticks between world snapshots (16: ~60 Hz)
  int queue_ticks = 2000;                       // samples the publishers may lag behind, in ticks
  // Periods over which the haptic side's anchor may cross the coupling's whole range
  // (max_force / stiffness) when the physics catches up after being late (>= 1; see above).
  int recovery_periods = 8;
  // Test seam, simulated time only (InputError otherwise): how many periods late the step that
  // takes tick k's targets completes (0: on time; d > 0: its result reaches the haptic side at
  // tick k + d, and the physics takes no targets meanwhile). Called once per step taken, from
  // tick(). Empty: every step on time.
  std::function<int(long tick)> physics_delay;
};
// rate, realtime_priority, real_time_factor, snapshot_every, queue_ticks: units, ranges,
// meanings (the device driver node reads rate and realtime_priority from it too).
const ParameterTable<ServoLoopParams>& servoLoopParameterTable();
std::string validate(const ServoLoopParams& params);

// One interface at one tick.
struct ServoSample
{
  long tick = 0;
  double time = 0.0;  // s, the loop clock's (simulated time, or seconds since the loop began)
  int interface = 0;
  DeviceReading reading;  // device frame; the last finite one
  // N, device frame, applied at this tick (a frame device's: the force decided for this reading).
  Eigen::Vector3d applied_force = Eigen::Vector3d::Zero();
  // N, device frame: the command for the next tick, the guard's input (saturated, before the
  // watchdog, soft start, continuous budget, rate limit and stop that give the next applied_force).
  Eigen::Vector3d commanded_force = Eigen::Vector3d::Zero();
  Eigen::Vector3d interface_position = Eigen::Vector3d::Zero();  // m, world (the device mapped)
  // World: an oriented finger's mapped orientation (the finger frame); identity for a 3-DOF one.
  Eigen::Quaterniond interface_orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d proxy_position = Eigen::Vector3d::Zero();  // m, world
  Eigen::Vector3d user_force = Eigen::Vector3d::Zero();      // N, world: the coupling's reaction
  // Oriented fingers: the rotational coupling's torque on the hand (N m, world), and the torque
  // sent with the next update (N m, device frame: on the profile's axes, saturated). Zero else.
  Eigen::Vector3d user_torque = Eigen::Vector3d::Zero();
  Eigen::Vector3d commanded_torque = Eigen::Vector3d::Zero();
  // N m, device frame: the torque given to the device at this tick (a commanded_torque of the
  // tick before, scaled by the guard, ForceGuard::scale).
  Eigen::Vector3d applied_torque = Eigen::Vector3d::Zero();
  double read_at = 0.0;    // s, steadySeconds() when the device was read
  double period_us = 0.0;  // since the previous tick began (wall clock)
  // From this device's reading to its force being ready (wall clock): simulated time, the
  // command; real time, a packet device's: the step's completion when on time, else the haptic
  // side's rendering (at the next tick's start), applied at the next tick's update; a frame
  // device's: the rendering at the read, applied in the same frame.
  double latency_us = 0.0;
  double step_us = 0.0;      // the world step whose result gave the force (wall clock)
  StepProfile step_profile;  // that step's stages (god_finger/physics/step_profile.h)
  // The force was rendered on the haptic side against the anchor (physics late, or recovering
  // from it), not the step's coupling reaction; user_force is then that rendering's.
  bool stale = false;
  // Ticks from the targets of the last completed step to this reading (on time: 0 for a packet
  // device, 1 for a frame device).
  long physics_lag = 0;
  // False: the device's source lost this finger (DeviceReading::tracked): the loop let it go.
  bool tracked = true;
  bool missing = false;  // untracked because the source's newest message lacked it (DeviceReading::missing)
};

// Counters since the loop began; readable from any thread.
struct ServoCounters
{
  std::atomic<long> ticks{0};
  std::atomic<long> overruns{0};
  std::atomic<long> dropped_samples{0};  // real time: the publishers were behind
  std::atomic<long> dropped_snapshots{0};
  std::atomic<long> rejected_readings{0};      // non-finite device readings (position or velocity)
  std::atomic<long> rejected_forces{0};        // non-finite forces refused by a guard
  std::atomic<long> untracked_readings{0};     // interface-ticks of fingers their source lost (let go)
  std::atomic<long> rejected_orientations{0};  // unusable orientations ignored (the position taken)
  std::atomic<long> commands{0};
  std::atomic<long> stale_ticks{0};      // interface-ticks whose force came from the anchor
  std::atomic<long> physics_steps{0};    // steps taken
  std::atomic<long> skipped_targets{0};  // targets the physics skipped, being late
  // Resets (a command or button 1), spawns and deletes the physics side applied, refused ones
  // included: what allocates on the physics thread (Bullet's world rebuilt for a reset, bodies
  // added or removed in it for an edit, the scene copied, the edit answered), so the step that applies one may be late.
  std::atomic<long> world_rebuilds{0};
  // The multi-rate hold's passivity controller (multirate_render.h): interface-ticks it damped
  // or cut at, the energy it took out (J), and the lowest its observer saw (J, any interface;
  // >= 0 while the controller is on).
  std::atomic<long> hold_damped_ticks{0};
  std::atomic<double> hold_dissipated{0.0};
  std::atomic<double> hold_lowest_energy{0.0};
  std::atomic<int> model{static_cast<int>(ContactModel::kGodFinger)};
  std::atomic<int> pad_solver{static_cast<int>(WorldParams().pad_solver)};  // the world's, after each step's commands
  std::atomic<bool> realtime{false};                                        // the haptic thread got SCHED_FIFO
  std::atomic<bool> failed{false};                                          // a device failed; the loop stopped
  std::atomic<bool> force_stopped{false};                                   // kStopForce applied, no kResumeForce since
};

// The two sides and their meeting place (src/runtime/, internal to runtime).
namespace internal
{
class HapticSide;
class PhysicsSide;
class PhysicsDelaySeam;
struct ServoMailboxes;
}  // namespace internal

class ServoLoop
{
 public:
  // Logs a message (warnings at start-up, the device failure); not called from tick().
  using Log = std::function<void(const std::string& message)>;

  // Throws InputError on bad parameters or an interface whose profile the world refuses.
  ServoLoop(std::unique_ptr<GodFingerWorld> world, std::vector<ServoInterface> interfaces,
            const ServoLoopParams& params, Log log = {});
  ~ServoLoop();
  ServoLoop(const ServoLoop&) = delete;
  ServoLoop& operator=(const ServoLoop&) = delete;

  // Starts the devices (DeviceError), reads each once at time 0 and puts its proxy there.
  // Allocates; call once, before tick() or start().
  void prepare();
  // One period at loop time `time` (s) on the calling thread: the haptic side, and on simulated
  // time the physics too. Real-time safe as above. Throws DeviceError from a device. On real
  // time, use start() (tick() alone would take no physics steps).
  void tick(double time);
  // Runs prepare() (if not yet done) and the loop in its own thread (and on real time the
  // physics in another) until stop().
  void start();
  void stop();
  bool running() const;

  // Any thread. False when the queue is full or the command is invalid (then `error` says why).
  // World commands go to the physics side, hand targets and the force stop to the haptic side.
  [[nodiscard]] bool post(const ServoCommand& command, std::string* error = nullptr);

  SpscQueue<ServoSample>& samples()
  {
    return samples_;
  }
  // The world after a step, every snapshot_every ticks, with the scene of that step
  // (WorldSnapshot::scene). Its `time` is on the loop's clock: the world's time plus the loop
  // time of the last reset (0 before any), so that it never goes back when a reset (a command,
  // button 1) sends the world's own time to 0 while the loop's clock, /clock on simulated time,
  // goes on; before a reset it is the world's time exactly.
  SpscQueue<WorldSnapshot>& snapshots()
  {
    return snapshots_;
  }
  const ServoCounters& counters() const
  {
    return counters_;
  }
  // The physics side's world, whole, while the loop is not running (before start(), after
  // stop(), or between two tick() calls from the thread that makes them). While it runs the world
  // is the physics thread's: its scene, bodies and states change (spawn_object and
  // delete_object change scene()), and another thread reads them from snapshots(); only
  // params().coupling and params().time_step, which nothing changes, may be read.
  const GodFingerWorld& world() const;
  // Names, profiles and mappings never change; the devices are the haptic side's.
  const std::vector<ServoInterface>& interfaces() const;
  const ServoLoopParams& params() const
  {
    return params_;
  }
  double period() const
  {
    return 1.0 / params_.rate;
  }

 private:
  void run();       // the loop's thread: starts and ends the physics thread on real time
  void runTicks();  // its loop

  ServoLoopParams params_;
  Log log_;
  ServoCounters counters_;                 // each written by one side (the commands count by both)
  SpscQueue<ServoSample> samples_;         // haptic side -> publishers
  SpscQueue<WorldSnapshot> snapshots_;     // physics side -> publishers
  SpscQueue<ServoCommand> commands_;       // post() -> physics side: world commands
  SpscQueue<ServoCommand> hand_commands_;  // post() -> haptic side: hand targets, force stop
  std::mutex post_mutex_;                  // producers of commands only; the loop never takes it
  std::atomic<bool> running_{false};
  std::atomic<bool> physics_running_{false};
  std::unique_ptr<internal::PhysicsSide> physics_;
  std::unique_ptr<internal::HapticSide> haptic_;
  std::unique_ptr<internal::ServoMailboxes> mail_;    // made by prepare()
  std::unique_ptr<internal::PhysicsDelaySeam> seam_;  // simulated time, made by prepare()
  std::thread thread_;
  std::thread physics_thread_;  // real time
  bool prepared_ = false;
  // The loop's clock: ticks done, and when the last began (s, steadySeconds()).
  long tick_ = 0;
  double last_tick_start_ = -1.0;
};
}  // namespace god_finger
