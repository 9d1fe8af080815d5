// The servo loop's haptic side (runtime/servo_loop.h): it owns the devices. Every period it
// exchanges with each device (the guarded force for its last reading out, a reading in), bounds
// and maps the reading into its interface's target (or lets the finger go, or rejects the
// reading), posts the tick's targets and presses for the physics, and decides the force for the
// reading from the last completed step (runtime/multirate_render.h: the step's reaction when on
// time, the hold's rendering when late), leaving one ServoSample per interface.
//
// Thread: the loop's (SCHED_FIFO realtime_priority on real time; tick()'s caller on simulated
// time). A frame device calls respond() from within exchangeFrame(), on the caller's thread or on
// its own servo thread while the caller waits: one thread at a time touches this side.
// Meets the physics side only through servo_mailboxes.h (writes the targets, reads the results;
// never waits for a step). Inputs: hand commands (SpscQueue, the consumer). Outputs: samples
// (SpscQueue, the producer; on simulated time it waits for the publishers), its counters.
// Real-time safe after prepare: no allocation, no log, no lock another thread holds (a fake
// device's hand-target lock is taken only by this thread).
// Units: s, m, N; device frame for device quantities, world for the rest.
#pragma once

#include "servo_mailboxes.h"

#include "god_finger/devices/haptic_device.h"
#include "god_finger/haptics/force_guard.h"
#include "god_finger/haptics/interface_input.h"
#include "god_finger/runtime/servo_loop.h"

#include <atomic>
#include <cmath>
#include <vector>

namespace god_finger::internal
{
class HapticSide : private FrameResponder
{
 public:
  // `running`: the loop's (reserveSlot).
  HapticSide(std::vector<ServoInterface> interfaces, const ServoLoopParams& params, ServoCounters* counters,
             SpscQueue<ServoCommand>* hand_commands, SpscQueue<ServoSample>* samples, const std::atomic<bool>& running);

  // Before the loop runs (allocates). Starts interface i's device and reads it at time 0: its
  // position bounded to the workspace and mapped into the world (DeviceError when not finite).
  Eigen::Vector3d startDevice(std::size_t i);
  // Before the loop runs: interface i starts at `start` (m, world), its proxy there, rendered
  // with `coupling` (the world's, for interface i).
  void placeInterface(std::size_t i, const Eigen::Vector3d& start, const CouplingProfile& coupling);
  // The targets and the step result the mailboxes start from (after every placeInterface).
  const TargetFrame& targets() const
  {
    return frame_;
  }
  const StepResult& latest() const
  {
    return latest_;
  }

  // Tick `tick` at loop time `time` (s), `period_us` after the last: every device's exchange (a
  // frame device's force decided within it), the hand commands, and the tick's targets posted
  // to `mail`. Its other devices' force is decided by decidePending().
  void exchange(long tick, double time, double period_us, ServoMailboxes* mail);
  // The force for the last exchange's readings (packet devices) and every interface's sample,
  // from the newest step in `mail` (or the last one taken): never waits for one. Nothing when
  // decided already. Real time: at the next tick's start; simulated time: after its step.
  void decidePending(ServoMailboxes* mail);

  const std::vector<ServoInterface>& interfaces() const
  {
    return interfaces_;
  }

 private:
  // The haptic side's state per interface (world frame).
  struct Render
  {
    Eigen::Vector3d target = Eigen::Vector3d::Zero();  // m: the last finite mapped reading
    Eigen::Vector3d previous_target = Eigen::Vector3d::Zero();
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // m/s: (target - previous_target) / dt
    Eigen::Vector3d previous_velocity = Eigen::Vector3d::Zero();
    MultirateState multirate;  // the anchor, the last decided force, exact or not (multirate_render.h)
    Eigen::Vector3d torque = Eigen::Vector3d::Zero();      // N m, device frame: renderable, the last decided
    Eigen::Vector3d wall_force = Eigen::Vector3d::Zero();  // N, device frame: haptics/workspace_bound.h
    bool stale = false;                                    // the last decision's
    bool tracked = true;                                   // the last reading's (DeviceReading::tracked)
    bool missing = false;                                  // the last reading's (DeviceReading::missing)
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

  // A frame device's exchange (FrameResponder): its reading in, this tick's wrench for it out.
  void respond(const DeviceReading& reading, Eigen::Vector3d* force, Eigen::Vector3d* torque) override;
  // Interface i's reading: bounded to the profile's workspace_radius (its wall force added to the
  // next command), mapped into its target; its presses into presses_. A reading whose position,
  // mapped position or velocity is not finite is rejected whole, counted (rejected_readings): no
  // press, the last good target, the samples carry the last good reading. An untracked one (a
  // finger its source lost) lets the finger go: its target on its proxy, the step taking zero
  // velocity (untracked_readings); tracked again, the target ramps to the pose over the guard's
  // soft start. An unusable orientation is ignored, counted (rejected_orientations), the
  // position taken.
  void takeReading(std::size_t i, const DeviceReading& reading);
  void applyHandCommands(double time);  // hand targets, force stop and resume; loop time (s)
  // Interface i's force for the reading of tick `tick` (loop time `time`) from latest_, and its
  // sample (a frame device's with its applied wrench).
  void decideInterface(std::size_t i, long tick, double time, double period_us);

  std::vector<ServoInterface> interfaces_;
  const double rate_;  // Hz
  const int recovery_periods_;
  const bool simulated_time_;
  ServoCounters* counters_;
  SpscQueue<ServoCommand>* hand_commands_;  // the consumer's end
  SpscQueue<ServoSample>* samples_;         // the producer's end
  const std::atomic<bool>& running_;
  std::vector<ForceGuard> guards_;
  std::vector<CouplingProfile> couplings_;  // the world's, copied at placeInterface
  // The multi-rate hold's passivity observer and controller per interface (the profile's
  // PassivityParams; multirate_render.h).
  std::vector<PassivityController> hold_passivity_;
  std::vector<InterfaceInput> inputs_;           // one per interface: bound, map, presses, orientation
  std::vector<DeviceReading> readings_;          // the last finite reading of each device
  std::vector<Eigen::Vector3d> applied_;         // N, device frame, given at this tick
  std::vector<Eigen::Vector3d> applied_torque_;  // N m, device frame, given at this tick
  std::vector<double> read_at_;                  // wall-clock seconds of each reading
  std::vector<Render> render_;
  std::vector<char> frame_exchange_;  // per interface: its device is DeviceExchange::kFrame
  long cycle_presses_ = 0;            // ticks with button 0 pressed, since the loop began
  long reset_presses_ = 0;            // same, button 1
  TargetFrame frame_;                 // this tick's targets
  StepResult latest_;                 // the last completed step taken from the mailbox
  // The tick whose force is undecided (exchange() to decidePending()), and, while a frame device
  // responds, its interface and the tick's presses.
  bool pending_ = false;
  long pending_tick_ = 0;
  double pending_time_ = 0.0;       // s, loop time
  double pending_period_us_ = 0.0;  // since the tick before
  std::size_t responding_ = 0;
  Presses presses_;
};
}  // namespace god_finger::internal
