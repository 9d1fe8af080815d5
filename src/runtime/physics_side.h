// The servo loop's physics side (runtime/servo_loop.h): it owns the world. One world step per
// targets frame it takes (the newest; older ones skipped when it is late, a free proxy carried
// across their motion: GodFingerWorld::carryFreeProxy), after the world commands and the
// buttons' presses that came in; then the step's result for the haptic side (per interface: the
// proxy after the step, its coupling reaction, its contact planes) and, every snapshot_every
// ticks, a WorldSnapshot for the publishers, on the loop's clock.
//
// Thread: on real time its own (SCHED_FIFO realtime_priority - 1; run()), woken by the
// mailboxes' PhysicsWake; on simulated time the loop's, in lockstep (physics_delay_seam.h).
// Nothing else touches the world while the loop runs (but for its coupling and time step, which
// never change: ServoLoop::world()); other threads read snapshots.
// Meets the haptic side only through servo_mailboxes.h. Inputs: the world commands (SpscQueue,
// the consumer). Outputs: results, snapshots (SpscQueue, the producer), its counters.
// Real-time: once warmed (its buffers grown to the scene's contacts) a step allocates nothing,
// and the haptic side never waits for it. What allocates, on this thread: a reset (a command or
// button 1), a spawn or a delete (Bullet's world rebuilt, or bodies added to or removed from it; the scene copied, the
// edit answered), each counted in world_rebuilds, and the snapshots after a spawn or a delete (their vectors take the
// new body count). Units: s, m, N, world frame.
#pragma once

#include "servo_mailboxes.h"

#include "god_finger/physics/god_finger_world.h"
#include "god_finger/runtime/servo_loop.h"

#include <atomic>
#include <memory>
#include <string>

namespace god_finger::internal
{
class PhysicsSide
{
 public:
  // `world` checked by the loop (a step of one period). `running`: the loop's (reserveSlot).
  PhysicsSide(std::unique_ptr<GodFingerWorld> world, const ServoLoopParams& params, std::size_t interfaces,
              ServoCounters* counters, SpscQueue<ServoCommand>* commands, SpscQueue<WorldSnapshot>* snapshots,
              const std::atomic<bool>& running);

  // Before the loop runs (allocates). Interface `name`'s proxy at `start` (m, world); its
  // coupling as the world keeps it. InputError, naming the interface, when the world refuses it
  // (a hand that starts inside a body).
  CouplingProfile addInterface(const std::string& name, const Eigen::Vector3d& start, const CouplingProfile& coupling);
  // Before the loop runs, after the interfaces (allocates): every snapshot slot sized once, so
  // that no step allocates for them.
  void prepare();

  // One step with `frame`'s targets; its result into `out` (sized as the frames).
  void step(const TargetFrame& frame, StepResult* out);
  // Real time: the physics thread, stepping every targets frame posted to `mail` until
  // `keep_running` goes false (true), or until the world throws (false, `error` says what).
  [[nodiscard]] bool run(ServoMailboxes* mail, const std::atomic<bool>& keep_running, std::string* error);

  GodFingerWorld& world()
  {
    return *world_;
  }

 private:
  void setTargets(const TargetFrame& frame);
  void applyCommands();
  void applyPresses(const TargetFrame& frame);
  void snapshotIfDue(long tick);

  std::unique_ptr<GodFingerWorld> world_;
  const double rate_;         // Hz: steps per second
  const int snapshot_every_;  // ticks
  const bool simulated_time_;
  const int realtime_priority_;  // the haptic thread's; this thread runs one below
  const std::size_t interfaces_;
  ServoCounters* counters_;
  SpscQueue<ServoCommand>* commands_;    // the consumer's end
  SpscQueue<WorldSnapshot>* snapshots_;  // the producer's end
  const std::atomic<bool>& running_;
  long last_frame_tick_ = -1;  // the tick of the last targets stepped
  long seen_cycle_presses_ = 0;
  long seen_reset_presses_ = 0;
  long next_snapshot_tick_ = 0;
  double world_time_offset_ = 0.0;  // s: loop time of the frame the last reset was applied in
};
}  // namespace god_finger::internal
