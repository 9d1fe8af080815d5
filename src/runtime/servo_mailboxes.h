// Where the servo loop's two sides meet (runtime/servo_loop.h): the haptic side's targets for the
// physics, the physics' step results for the haptic side, and the semaphore that wakes the
// physics thread. Nothing else passes between haptic_side.h and physics_side.h while the loop
// runs. Internal to runtime.
//
// Invariants: every TargetFrame and StepResult of one loop has one length per vector (the
// interface count), fixed at prepare(), so that copying one into a slot allocates nothing. The
// targets box is written by the haptic side and read by the physics side, the results box the
// other way (support/latest_value.h: one writer, one reader, the newest value wins; older ones
// are skipped). Real-time safe: both boxes, PhysicsWake::post (a POSIX semaphore's post is
// lock-free) and reserveSlot without waiting (real time).
// Units: s, m, N, world frame.
#pragma once

#include "god_finger/physics/step_profile.h"
#include "god_finger/runtime/multirate_render.h"
#include "god_finger/runtime/servo_clock.h"
#include "god_finger/support/latest_value.h"
#include "god_finger/support/spsc_queue.h"

#include <semaphore.h>
#include <time.h>
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <atomic>
#include <limits>
#include <vector>

namespace god_finger::internal
{
// Haptic -> physics: one tick's targets.
struct TargetFrame
{
  long tick = -1;
  double time = 0.0;                        // s, the loop time of that tick
  double read_at = 0.0;                     // s, steadySeconds() of the first device's reading
  long cycle_presses = 0;                   // ticks on which button 0 was pressed, since the loop began
  long reset_presses = 0;                   // same, button 1
  std::vector<Eigen::Vector3d> targets;     // m, world: the mapped readings (always finite)
  std::vector<Eigen::Vector3d> velocities;  // m/s, world: the haptic side's estimate
  // Per interface, 1 while its finger is let go (untracked): the step takes its velocity
  // (zero: the target rests on the proxy) instead of the targets' difference, so the jump of
  // the target onto the proxy kicks nothing and the damping brings the released proxy to rest.
  std::vector<unsigned char> let_go;
  // World, unit: the last usable mapped orientation, where oriented[i] (the device reported one).
  std::vector<Eigen::Quaterniond> orientations;
  std::vector<char> oriented;
};

// Physics -> haptic: the intermediate representation of one interface's contact after a step.
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

// Physics -> haptic: one completed step.
struct StepResult
{
  long tick = -1;        // the tick whose targets the step took; -1: none yet (proxies at their start)
  double done_at = 0.0;  // s, steadySeconds()
  double step_us = 0.0;  // the world step's wall-clock time
  StepProfile step_profile;
  std::vector<ProxyResult> proxies;  // one per interface
};

// Wakes the physics thread when targets are posted (real time).
class PhysicsWake
{
 public:
  PhysicsWake()
  {
    sem_init(&semaphore_, 0, 0);
  }
  ~PhysicsWake()
  {
    sem_destroy(&semaphore_);
  }
  PhysicsWake(const PhysicsWake&) = delete;
  PhysicsWake& operator=(const PhysicsWake&) = delete;
  // Any thread; real-time safe. Posts accumulate while the physics steps.
  void post()
  {
    sem_post(&semaphore_);
  }
  // The physics thread: until a post, or 20 ms (so that it looks at its stop flag that often).
  void wait()
  {
    timespec deadline;
    clock_gettime(CLOCK_REALTIME, &deadline);
    deadline.tv_nsec += 20000000;
    if (deadline.tv_nsec >= 1000000000)
    {
      deadline.tv_nsec -= 1000000000;
      ++deadline.tv_sec;
    }
    sem_timedwait(&semaphore_, &deadline);
  }

 private:
  sem_t semaphore_;
};

// Made at prepare(), from the haptic side's first targets and its proxies at their start.
struct ServoMailboxes
{
  ServoMailboxes(const TargetFrame& first_targets, const StepResult& start) : targets(first_targets), results(start) {}
  LatestValue<TargetFrame> targets;  // haptic side writes, physics side reads
  LatestValue<StepResult> results;   // physics side writes, haptic side reads
  PhysicsWake wake;                  // real time: posted with every targets frame
};

// A slot of `queue` for one output (samples(), snapshots()); null when it is full. With `wait`
// (simulated time: the publishers get everything) it waits for one in 100 us sleeps while
// `running` (a loop driven by tick() alone is not running: it never waits).
template <class T>
T* reserveSlot(SpscQueue<T>& queue, bool wait, const std::atomic<bool>& running)
{
  T* slot = queue.reserve();
  while (!slot && wait && running)
  {
    sleepFor(100e-6);
    slot = queue.reserve();
  }
  return slot;
}
}  // namespace god_finger::internal
