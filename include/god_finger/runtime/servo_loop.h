// The haptic servo loop: what the hand feels, in one thread, without ROS (CHAI3D's haptic
// thread, ros_control's real-time/non-real-time split). Every period it
//   1. applies to every device the force its guard gives now and reads the device;
//   2. maps each reading into the world (the interface target; non-finite ones are rejected);
//   3. applies the commands that came in (contact model, contact parameters, reset, hand
//      targets) and the devices' buttons (0: next contact model, 1: reset);
//   4. steps the world (the coupling pulls each proxy with its device's profile);
//   5. commands each device the opposite of its proxy's coupling force, through its guard
//      (saturation, NaN rejection, watchdog), applied at the next period's update;
//   6. leaves a sample per interface, and every few periods a world snapshot, in lock-free
//      queues for the publishers.
//
// Clocks: real time (CLOCK_MONOTONIC, absolute deadlines, so the rate does not drift; a late
// period is an overrun, counted; far behind, the schedule restarts from now) or simulated
// time (t = tick / rate exactly; paced at real_time_factor times the wall clock, or as fast as
// it goes with 0). On simulated time the loop is deterministic: the same devices give the same
// trajectory bit for bit, whatever the machine's load, and it waits for the publishers instead
// of dropping their samples.
//
// Real-time safety: tick() neither allocates (after prepare()) nor logs, and takes no lock
// another thread holds (the fake device's hand-target lock is taken only by the loop thread
// here), except when it applies a reset, which rebuilds the Bullet world (an overrun); the
// loop thread runs at SCHED_FIFO `realtime_priority` and locks its memory when permitted (a
// warning through the log callback otherwise). Outputs: samples() and snapshots() (the
// publisher thread is their one consumer). Inputs: post() (any thread; producers serialise
// among themselves, never with the loop).
//
// Units: s, m, N; device frame for device quantities, world for the rest.
#pragma once

#include "god_finger/core/device_profile.h"
#include "god_finger/core/parameter_table.h"
#include "god_finger/core/spsc_queue.h"
#include "god_finger/core/workspace_mapping.h"
#include "god_finger/devices/haptic_device.h"
#include "god_finger/physics/god_finger_world.h"

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace god_finger
{
struct ServoInterface
{
  std::string name;
  std::unique_ptr<HapticDevice> device;
  DeviceProfile profile;
  WorkspaceMapping mapping;
};

struct ServoLoopParams
{
  double rate = 1000.0;           // Hz: the device rate; the world's step is 1 / rate
  int realtime_priority = 80;     // SCHED_FIFO priority of the loop thread, 0 for none
  bool lock_memory = true;        // mlockall when permitted
  bool simulated_time = false;    // see above
  double real_time_factor = 1.0;  // simulated time only; 0: as fast as it goes
  int snapshot_every = 16;        // ticks between world snapshots (16: ~60 Hz)
  int queue_ticks = 2000;         // samples the publishers may lag behind, in ticks
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
  DeviceReading reading;                                         // device frame
  Eigen::Vector3d applied_force = Eigen::Vector3d::Zero();       // N, device frame, applied at this tick
  Eigen::Vector3d commanded_force = Eigen::Vector3d::Zero();     // N, device frame, for the next tick
  Eigen::Vector3d interface_position = Eigen::Vector3d::Zero();  // m, world (the device mapped)
  Eigen::Vector3d proxy_position = Eigen::Vector3d::Zero();      // m, world
  Eigen::Vector3d user_force = Eigen::Vector3d::Zero();          // N, world: the coupling's reaction
  double read_at = 0.0;                                          // s, steadySeconds() when the device was read
  double period_us = 0.0;                                        // since the previous tick began (wall clock)
  double latency_us = 0.0;  // from this device's reading to its force command (wall clock)
  double step_us = 0.0;     // the world step (wall clock)
};

struct ServoCommand
{
  enum class Kind
  {
    kSetContactModel,
    kSetContactParams,
    kReset,
    kHandTarget,
  };
  Kind kind = Kind::kReset;
  ContactModel model = ContactModel::kGodFinger;
  ContactParams contact;  // validated by post()
  int interface = 0;
  Eigen::Vector3d hand_target = Eigen::Vector3d::Zero();  // m, device frame
};

// Counters since the loop began; readable from any thread.
struct ServoCounters
{
  std::atomic<long> ticks{0};
  std::atomic<long> overruns{0};
  std::atomic<long> dropped_samples{0};  // real time: the publishers were behind
  std::atomic<long> dropped_snapshots{0};
  std::atomic<long> rejected_readings{0};  // non-finite device positions
  std::atomic<long> rejected_forces{0};    // non-finite forces refused by a guard
  std::atomic<long> commands{0};
  std::atomic<int> model{static_cast<int>(ContactModel::kGodFinger)};
  std::atomic<bool> realtime{false};  // the thread got SCHED_FIFO
  std::atomic<bool> failed{false};    // a device failed; the loop stopped
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
  // One period at loop time `time` (s). Real-time safe. Throws DeviceError from a device.
  void tick(double time);
  // Runs prepare() (if not yet done) and the loop in its own thread until stop().
  void start();
  void stop();
  bool running() const;

  // Any thread. False when the queue is full or the command is invalid (then `error` says why).
  bool post(const ServoCommand& command, std::string* error = nullptr);

  SpscQueue<ServoSample>& samples()
  {
    return samples_;
  }
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
  void applyCommands();
  void run();
  template <class T>
  T* reserveIn(SpscQueue<T>& queue);

  std::unique_ptr<GodFingerWorld> world_;
  std::vector<ServoInterface> interfaces_;
  ServoLoopParams params_;
  Log log_;
  std::vector<ForceGuard> guards_;
  std::vector<std::uint32_t> buttons_;
  std::vector<DeviceReading> readings_;
  std::vector<Eigen::Vector3d> applied_;
  std::vector<double> read_at_;  // wall-clock seconds of each reading
  SpscQueue<ServoSample> samples_;
  SpscQueue<WorldSnapshot> snapshots_;
  SpscQueue<ServoCommand> commands_;
  std::mutex post_mutex_;  // producers of commands only; the loop never takes it
  ServoCounters counters_;
  std::thread thread_;
  std::atomic<bool> running_{false};
  bool prepared_ = false;
  long tick_ = 0;
  double last_tick_start_ = -1.0;
};
}  // namespace god_finger
