// The haptic servo loop: what the hand feels, without ROS (CHAI3D's haptic thread, ros_control's
// real-time/non-real-time split), in two rates: the multi-rate scheme of 6-DOF haptic
// rendering (Ortega, Redon, Coquillart 2007; Knott, Kuhlen 2015). The device's period is
// sacred, the physics' is not.
//
// The haptic side, every period:
//   1. commands each device a force (below), through its guard (saturation, NaN rejection,
//      watchdog), and applies it at this period's update, which reads the device;
//   2. bounds each reading to the profile's workspace_radius (haptics/workspace_bound.h: a reading
//      beyond it is clamped and its wall force added to the next command), maps it into the
//      world (the interface target) and hands the targets and the
//      buttons' presses (0: next contact model, 1: reset) to the physics (button 2, where
//      the device has one, e.g. the Falcon's third, stops every device's force or resumes it
//      with the soft start, as kStopForce / kResumeForce); applies the
//      hand-target commands. A reading whose position, mapped position or velocity is not
//      finite is rejected whole and counted once (rejected_readings), as the topic topologies'
//      haptic node does: its buttons press nothing, the physics gets the last good target
//      (the world never sees a non-finite one), and its sample carries the last good reading;
//      a reading its source marks untracked (a finger a pose source lost, DeviceReading::tracked)
//      lets that finger go: its target is its proxy's last position (no coupling force; the
//      step takes its velocity as zero, so the released proxy comes to rest), counted
//      in untracked_readings, its sample says tracked = false; the other interfaces go on;
//      tracked again, its target ramps from that proxy position to the tracked pose over the
//      force guard's soft start (softStartScale, haptics/force_guard.h): no step of coupling force;
//   3. leaves a sample per interface in a lock-free queue for the publishers.
// Oriented fingers (a reading with has_orientation, physics/oriented_finger.h): the reading's
// orientation, mapped into the world (WorkspaceMapping::orientationToWorld), goes to the
// physics with the position (GodFingerWorld::setInterfaceTarget's quaternion overload), and the
// rotational coupling's torque on the hand (InterfaceState::user_torque, world) comes back,
// mapped into the device frame (torqueToDevice) and cut to the profile's torque axes and
// max_torque (renderableTorque, haptics/device_profile.h): it is sent at the next tick's update
// (HapticDevice::updateWrench) with the force, zero while the guard is stopped. It is the last
// completed step's torque, also while the physics is late (no haptic-side rendering of torque).
// An orientation that is not usable (non-finite, norm outside [0.5, 2]: haptics/orientation_path.h
// usableOrientation) is ignored and counted (rejected_orientations): the finger keeps its last
// good orientation (a 3-DOF finger until it had one); the position is still taken. A finger
// whose device never reports an orientation runs exactly the 3-DOF calls, bit for bit.
// The physics side, one step per targets it takes (the latest; older ones are skipped when it
// is late, the skipped motion entering the coupling's damping as the device's velocity):
// applies the world commands that came in (contact model, contact parameters, reset) and the
// presses, steps the world (the coupling pulls each proxy with its device's profile) and
// publishes the intermediate representation of the contact, per interface: the proxy position
// after the step and the step's coupling reaction (InterfaceState::user_force); every few steps
// a world snapshot for the publishers.
//
// A frame device (HapticDevice::exchangeForm() kFrame: the Omni/Touch's servo frame) is read,
// answered and written in one exchange (exchangeFrame): the loop takes its reading and decides
// its force within it, from the last completed step (the one that took tick k - 1's targets when
// on time: physics_lag 1, not stale), rendered at the read as below (the step's proxy while the
// device presses into one of its planes, the device itself otherwise), and the device applies it
// in the same frame, a period sooner than a packet device's. On time it runs without the hold's
// controller, as a packet device's exact force does; late (lag > 1) its hold begins as below.
// The force for the reading of tick k of a packet device (applied at tick k + 1's update), per
// interface:
//  - on time (the last completed step took tick k's targets) and exact: the step's coupling
//    reaction, bit for bit what a single-rate loop commands;
//  - late ("stale", physics lag k - j > 0 for the last completed step j): the virtual coupling
//    rendered on the haptic side against an anchor a, a spring plus damping on the device's
//    velocity relative to the anchor's prediction (runtime/multirate_render.h):
//      F = -sat(k_c (p_I - a) + b (v_I - v_a), max_force)      (CouplingProfile of the interface)
//    with p_I, v_I the device's target and velocity ((p_I,k - p_I,k-1) / dt) in the world;
//  - the anchor rule: in exact mode a is the last completed step's proxy position; out of it a
//    moves toward the step's predicted proxy (the step's proxy while the device presses into
//    one of the step's contact planes, the device itself otherwise: a wall and its friction
//    hold, free space stays free; there at once when it is the device) by at most
//      delta + |p_I,k - p_I,k-1|,   delta = max_force / (k_c recovery_periods)   per period
//    (so a proxy jump that the catching-up physics makes reaches the hand over at least
//    recovery_periods periods per max_force of spring), and the commanded force moves toward
//    the rendering by at most the force-step bound
//      B_k = k_c (|p_I,k - p_I,k-1| + delta) + b |v_I,k - v_I,k-1|
//    Back to exact when on time, the anchor on the proxy and the step's force within B_k of the
//    last command. So every change of force out of exact mode is at most B_k.
//    Energy: a spring to a fixed anchor or to the device itself plus damping is passive; what a
//    new step's planes or proxy bring under a stretched spring, the hold's passivity observer and
//    controller (the profile's PassivityParams, haptics/passivity_controller.h) keep within
//    what the coupling stored when the hold began plus what the hand put in since.
//    test/runtime/multirate_test.cpp measures it over 5 and 20 ms stalls: never more energy
//    to the device than the on-time loop gives, none while the hand presses; a hand moving
//    through free space during a stall feels no drag.
//
// Threads and clocks:
//  - Real time (CLOCK_MONOTONIC, the deadlines of runtime/fixed_rate_schedule.h, so the rate
//    does not drift; a late period is an overrun, counted; far behind, the schedule restarts
//    from now): the haptic thread
//    (SCHED_FIFO `realtime_priority`) does the device I/O and never waits for the physics; the
//    physics thread (SCHED_FIFO realtime_priority - 1, normal scheduling when that is 0) steps
//    when new targets are posted (a POSIX semaphore, whose post is lock-free). Mailboxes:
//    targets and results are latest-value triple buffers (support/latest_value.h), commands SPSC
//    queues (world commands to the physics thread, hand targets to the haptic thread). The
//    force for tick k's reading is decided at the start of tick k + 1, just before the update
//    that applies it, from whatever step completed by then.
//  - Simulated time (t = tick / rate exactly; paced at real_time_factor times the wall clock,
//    or as fast as it goes with 0): one thread, lockstep, the physics never lags; the same
//    devices give the same trajectory bit for bit, whatever the machine's load, and the loop
//    waits for the publishers instead of dropping their samples. Its test seam
//    (ServoLoopParams::physics_delay) makes chosen steps late by whole periods,
//    deterministically.
//
// Real-time safety: tick() neither allocates (after prepare()) nor logs nor takes a lock
// another thread holds (the fake device's hand-target lock is taken only by the haptic thread);
// the physics thread allocates only when it applies a reset (it rebuilds the Bullet world), and
// the haptic thread never waits for it. Both lock their memory when permitted (a warning
// through the log callback otherwise). Outputs: samples() (haptic thread) and snapshots()
// (physics thread; the publisher thread is the one consumer of each). Inputs: post() (any
// thread; producers serialise among themselves, never with the loop).
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
#include "god_finger/support/latest_value.h"
#include "god_finger/support/parameter_table.h"
#include "god_finger/support/spsc_queue.h"

#include <semaphore.h>
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
  // time the physics too. Real-time safe. Throws DeviceError from a device. On real time, use
  // start() (tick() alone would take no physics steps).
  void tick(double time);
  // Runs prepare() (if not yet done) and the loop in its own thread (and on real time the
  // physics in another) until stop().
  void start();
  void stop();
  bool running() const;

  // Any thread. False when the queue is full or the command is invalid (then `error` says why).
  bool post(const ServoCommand& command, std::string* error = nullptr);

  SpscQueue<ServoSample>& samples()
  {
    return samples_;
  }
  // The world after a step, every snapshot_every ticks. Its `time` is on the loop's clock: the
  // world's time plus the loop time of the last reset (0 before any), so that it never goes
  // back when a reset (a command, button 1) sends the world's own time to 0 while the loop's
  // clock, /clock on simulated time, goes on; before a reset it is the world's time exactly.
  SpscQueue<WorldSnapshot>& snapshots()
  {
    return snapshots_;
  }
  const ServoCounters& counters() const
  {
    return counters_;
  }
  // From another thread while the loop runs, only what never changes: world().scene(),
  // world().params().coupling and time_step, interfaces()' names and profiles, params(). The
  // rest (model, contact parameters, states) belongs to the loop thread; observers read
  // snapshots().
  const GodFingerWorld& world() const
  {
    return *world_;
  }
  const std::vector<ServoInterface>& interfaces() const
  {
    return interfaces_;
  }
  const ServoLoopParams& params() const
  {
    return params_;
  }
  double period() const
  {
    return 1.0 / params_.rate;
  }

 private:
  // Haptic -> physics: one tick's targets.
  struct TargetFrame
  {
    long tick = -1;
    double time = 0.0;                        // s, the loop time of that tick
    double read_at = 0.0;                     // s, steadySeconds() of the first device's reading
    long cycle_presses = 0;                   // ticks on which button 0 was pressed, since the loop began
    long reset_presses = 0;                   // same, button 1
    std::vector<Eigen::Vector3d> targets;     // m, world: the mapped readings (maybe non-finite)
    std::vector<Eigen::Vector3d> velocities;  // m/s, world: the haptic side's estimate
    // Per interface, 1 while its finger is let go (untracked): the step takes its velocity
    // (zero: the target rests on the proxy) instead of the targets' difference, so the jump of
    // the target onto the proxy kicks nothing and the damping brings the released proxy to rest.
    std::vector<unsigned char> let_go;
    // World, unit: the last usable mapped orientation, where oriented[i] (the device reported one).
    std::vector<Eigen::Quaterniond> orientations;
    std::vector<char> oriented;
  };
  // Physics -> haptic: the intermediate representation from one completed step.
  struct ProxyResult
  {
    Eigen::Vector3d proxy_position = Eigen::Vector3d::Zero();  // m, world, after the step
    Eigen::Vector3d user_force = Eigen::Vector3d::Zero();      // N, world: the step's coupling reaction
    Eigen::Vector3d user_torque = Eigen::Vector3d::Zero();     // N m, world: the rotational coupling's
    // The step's device target (m, world) and its contact's stiffness along its normal
    // (InterfaceState::contact_stiffness: finite on a soft body), for the multi-rate renderer.
    Eigen::Vector3d interface_position = Eigen::Vector3d::Zero();
    double contact_stiffness = std::numeric_limits<double>::infinity();
    Eigen::Vector3d contact_normal = Eigen::Vector3d::UnitZ();
    // The step's contact planes through proxy_position (MultirateStep::plane_normals).
    int plane_count = 0;
    std::array<Eigen::Vector3d, MultirateStep::kMaxPlanes> plane_normals{};
  };
  struct StepResult
  {
    long tick = -1;  // the tick whose targets the step took; -1: none yet (proxies at their start)
    double done_at = 0.0;
    double step_us = 0.0;
    StepProfile step_profile;
    std::vector<ProxyResult> proxies;
  };
  // The haptic side's state per interface (world frame).
  struct Render
  {
    Eigen::Vector3d target = Eigen::Vector3d::Zero();  // m: the last finite mapped reading
    Eigen::Vector3d previous_target = Eigen::Vector3d::Zero();
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // m/s: (target - previous_target) / dt
    Eigen::Vector3d previous_velocity = Eigen::Vector3d::Zero();
    MultirateState multirate;  // the anchor, the last decided force, exact or not (multirate_render.h)
    Eigen::Vector3d torque = Eigen::Vector3d::Zero();  // N m, device frame: renderable, the last decided
    Eigen::Vector3d wall_force =
        Eigen::Vector3d::Zero();  // N, device frame: the workspace wall (haptics/workspace_bound.h)
    bool stale = false;           // the last decision's
    bool tracked = true;          // the last reading's (DeviceReading::tracked)
    bool missing = false;         // the last reading's (DeviceReading::missing)
    // A finger tracked again: its target ramps from regrip_from (m, world: where it let go) to
    // the tracked pose with the force guard's soft start from regrip_at (s, loop time).
    Eigen::Vector3d regrip_from = Eigen::Vector3d::Zero();
    double regrip_at = -INFINITY;
    double ready_at = 0.0;    // s, wall: when the last decision's force was ready
    bool frame_held = false;  // a frame device's last decision was late (its hold under way)
  };
  // One tick's button presses over every interface.
  struct Presses
  {
    bool cycle_model = false;
    bool reset = false;
    bool toggle_stop = false;
  };
  class FrameStep;  // a kFrame device's responder (servo_loop.cpp)

  // Every device's exchange this tick (a frame device's force decided within it, at `period_us`).
  void readDevices(double time, double period_us);
  // Interface i's reading: bounded, mapped, into its target; its presses added to `presses`.
  void takeReading(std::size_t i, const DeviceReading& reading, double time, Presses* presses);
  void applyHandTargets(double time);  // hand targets, force stop and resume; loop time (s)
  void applyWorldCommands();
  // Physics side: one step with `frame`'s targets; fills `out`.
  void stepFrame(const TargetFrame& frame, StepResult* out);
  // Simulated time: the physics of this tick, lockstep, through the stall seam.
  void physicsInline();
  // Haptic side: the force for tick `tick`'s reading (loop time `time`), from latest_, for every
  // packet device (decideInterface: one interface; a frame device's, with its applied wrench).
  void decide(long tick, double time, double period_us);
  void decideInterface(std::size_t i, long tick, double time, double period_us);
  void run();       // the haptic thread: starts and ends the physics thread on real time
  void runTicks();  // its loop
  void runPhysics();
  template <class T>
  T* reserveIn(SpscQueue<T>& queue);

  std::unique_ptr<GodFingerWorld> world_;
  std::vector<ServoInterface> interfaces_;
  ServoLoopParams params_;
  Log log_;
  std::vector<ForceGuard> guards_;
  std::vector<CouplingProfile> couplings_;  // the world's, copied for the haptic side
  // The multi-rate hold's passivity observer and controller per interface (the profile's
  // PassivityParams; multirate_render.h), haptic side only.
  std::vector<PassivityController> hold_passivity_;
  std::vector<InterfaceInput> inputs_;   // one per interface: bound, map, presses, orientation
  std::vector<DeviceReading> readings_;  // the last finite reading of each device
  std::vector<Eigen::Vector3d> applied_;
  std::vector<Eigen::Vector3d> applied_torque_;  // N m, device frame, given at this tick
  std::vector<double> read_at_;                  // wall-clock seconds of each reading
  std::vector<Render> render_;
  std::vector<char> frame_exchange_;  // per interface: its device is DeviceExchange::kFrame
  long cycle_presses_ = 0;            // haptic side's counts
  long reset_presses_ = 0;
  SpscQueue<ServoSample> samples_;
  SpscQueue<WorldSnapshot> snapshots_;
  SpscQueue<ServoCommand> commands_;       // world commands: consumed by the physics
  SpscQueue<ServoCommand> hand_commands_;  // hand targets: consumed by the haptic side
  std::mutex post_mutex_;                  // producers of commands only; the loop never takes it
  ServoCounters counters_;
  std::thread thread_;
  std::thread physics_thread_;
  std::atomic<bool> running_{false};
  std::atomic<bool> physics_running_{false};
  bool prepared_ = false;
  long tick_ = 0;
  double last_tick_start_ = -1.0;
  double pending_time_ = 0.0;       // real time: loop time of the tick whose force is undecided
  double pending_period_us_ = 0.0;  // and its period
  bool pending_ = false;
  // Haptic side's mailboxes' ends and its copy of the last completed step.
  TargetFrame frame_;  // simulated time: this tick's targets
  StepResult latest_;
  std::unique_ptr<LatestValue<TargetFrame>> targets_box_;  // real time
  std::unique_ptr<LatestValue<StepResult>> results_box_;   // real time
  sem_t physics_wake_;
  // Physics side.
  long last_frame_tick_ = -1;
  long seen_cycle_presses_ = 0;
  long seen_reset_presses_ = 0;
  long next_snapshot_tick_ = 0;
  double world_time_offset_ = 0.0;  // s: loop time of the frame the last reset was applied in
  TargetFrame seam_frame_;          // simulated time: the targets of the late step in progress
  bool seam_busy_ = false;
  long seam_ready_tick_ = 0;
  StepResult seam_result_;
};
}  // namespace god_finger
