#include "haptic_side.h"

#include "god_finger/haptics/workspace_bound.h"
#include "god_finger/runtime/servo_clock.h"
#include "god_finger/support/contract.h"

#include <algorithm>

namespace god_finger::internal
{
namespace
{
InterfaceReading interfaceReading(const DeviceReading& reading)
{
  InterfaceReading input;
  input.position = reading.position;
  input.velocity = reading.velocity;
  input.buttons = reading.buttons;
  input.has_orientation = reading.has_orientation;
  input.orientation = reading.orientation;
  return input;
}
}  // namespace

HapticSide::HapticSide(std::vector<ServoInterface> interfaces, const ServoLoopParams& params, ServoCounters* counters,
                       SpscQueue<ServoCommand>* hand_commands, SpscQueue<ServoSample>* samples,
                       const std::atomic<bool>& running)
    : interfaces_(std::move(interfaces)),
      rate_(params.rate),
      recovery_periods_(params.recovery_periods),
      simulated_time_(params.simulated_time),
      counters_(counters),
      hand_commands_(hand_commands),
      samples_(samples),
      running_(running),
      couplings_(interfaces_.size()),
      readings_(interfaces_.size()),
      applied_(interfaces_.size(), Eigen::Vector3d::Zero()),
      applied_torque_(interfaces_.size(), Eigen::Vector3d::Zero()),
      read_at_(interfaces_.size(), 0.0),
      render_(interfaces_.size())
{
  const std::size_t n = interfaces_.size();
  for (const ServoInterface& interface : interfaces_)
  {
    guards_.emplace_back(interface.profile.coupling.max_force, interface.profile.guard);
    hold_passivity_.emplace_back(interface.profile.passivity, 1.0 / rate_);
    inputs_.emplace_back(interface.profile, interface.mapping);
    frame_exchange_.push_back(interface.device->exchangeForm() == DeviceExchange::kFrame ? 1 : 0);
  }
  latest_.proxies.resize(n);
  frame_.targets.resize(n);
  frame_.velocities.resize(n, Eigen::Vector3d::Zero());
  frame_.let_go.resize(n, 0);
  frame_.orientations.resize(n, Eigen::Quaterniond::Identity());
  frame_.oriented.resize(n, 0);
}

Eigen::Vector3d HapticSide::startDevice(std::size_t i)
{
  ServoInterface& interface = interfaces_[i];
  interface.device->start();
  readings_[i] = interface.device->update(0.0, Eigen::Vector3d::Zero());
  // Within the workspace (haptics/workspace_bound.h), as every later reading.
  const Eigen::Vector3d start =
      interface.mapping.toWorld(boundToWorkspace(readings_[i].position, interface.profile, interface.mapping).position);
  if (!start.allFinite())
  {
    throw DeviceError("interface '" + interface.name + "': the device's first position is not finite");
  }
  if (!readings_[i].velocity.allFinite())
  {
    readings_[i].velocity.setZero();  // the samples carry finite readings only
  }
  return start;
}

void HapticSide::placeInterface(std::size_t i, const Eigen::Vector3d& start, const CouplingProfile& coupling)
{
  couplings_[i] = coupling;
  Render& render = render_[i];
  render.target = render.previous_target = render.multirate.anchor = start;
  latest_.proxies[i].proxy_position = start;
  frame_.targets[i] = start;
}

void HapticSide::applyHandCommands(double time)
{
  ServoCommand command;
  while (hand_commands_->tryPop(&command))
  {
    ++counters_->commands;
    if (command.kind == ServoCommand::Kind::kStopForce)
    {
      for (ForceGuard& guard : guards_)
      {
        guard.stop();
      }
    }
    else if (command.kind == ServoCommand::Kind::kResumeForce)
    {
      for (ForceGuard& guard : guards_)
      {
        guard.resume(time);
      }
    }
    else
    {
      GOD_FINGER_EXPECTS(command.interface >= 0 && command.interface < static_cast<int>(interfaces_.size()),
                         "ServoLoop::post checks a hand command's interface before queueing it");
      HapticDevice& device = *interfaces_[command.interface].device;
      if (command.hand_oriented)
      {
        device.setHandPose(command.hand_target, command.hand_orientation);
      }
      else
      {
        device.setHandTarget(command.hand_target);
      }
    }
  }
  counters_->force_stopped = !guards_.empty() && guards_[0].stopped();
}

void HapticSide::respond(const DeviceReading& reading, Eigen::Vector3d* force, Eigen::Vector3d* torque)
{
  takeReading(responding_, reading);
  decideInterface(responding_, pending_tick_, pending_time_, pending_period_us_);
  *force = applied_[responding_];
  *torque = applied_torque_[responding_];
}

void HapticSide::exchange(long tick, double time, double period_us, ServoMailboxes* mail)
{
  const support::RealTimeSection real_time;  // after prepare: no allocation (checked without NDEBUG)
  pending_tick_ = tick;
  pending_time_ = time;
  pending_period_us_ = period_us;
  presses_ = Presses();
  for (std::size_t i = 0; i < interfaces_.size(); ++i)
  {
    ServoInterface& interface = interfaces_[i];
    if (frame_exchange_[i])
    {
      responding_ = i;
      interface.device->exchangeFrame(time, *this);  // respond(): its force decided within
      continue;
    }
    applied_[i] = guards_[i].output(time);
    // The torque decided for the last reading (zero for a device with no torque axes), through
    // the force's guard: its soft start and watchdog ramp, zero while the force is stopped.
    applied_torque_[i] = guards_[i].scale(time) * render_[i].torque;
    takeReading(i, interface.device->updateWrench(time, applied_[i], applied_torque_[i]));
  }
  if (presses_.toggle_stop)  // button 2: stop every device's force, or resume it (soft start)
  {
    const bool stop = !guards_.empty() && !guards_[0].stopped();
    for (ForceGuard& guard : guards_)
    {
      stop ? guard.stop() : guard.resume(time);
    }
    counters_->force_stopped = stop;
  }
  cycle_presses_ += presses_.cycle_model ? 1 : 0;
  reset_presses_ += presses_.reset ? 1 : 0;
  frame_.tick = tick;
  frame_.time = time;
  frame_.read_at = read_at_[0];
  frame_.cycle_presses = cycle_presses_;
  frame_.reset_presses = reset_presses_;
  applyHandCommands(time);
  mail->targets.back() = frame_;  // same lengths: no allocation
  mail->targets.publish();
  pending_ = true;
}

void HapticSide::takeReading(std::size_t i, const DeviceReading& reading)
{
  const double time = pending_time_;
  const double dt = 1.0 / rate_;
  read_at_[i] = steadySeconds();
  Render& render = render_[i];
  render.previous_target = render.target;
  // A non-finite reading is rejected here, once, as a whole (as the haptic node rejects a
  // non-finite device state): its buttons are not pressed, the world gets the last good
  // target, and the samples (device/state) carry the last good reading.
  const bool was_tracked = render.tracked;
  render.tracked = reading.tracked;
  render.missing = reading.missing;
  if (!reading.tracked)
  {
    // A finger its source lost (devices/hand_device.h) lets go: its target follows its proxy
    // (no coupling force, the proxy released) until the source sees it again.
    ++counters_->untracked_readings;
    render.target = latest_.proxies[i].proxy_position;
    render.previous_target = render.target;
    render.wall_force.setZero();
  }
  else if (const InterfaceInputResult input = inputs_[i].read(interfaceReading(reading)); input.accepted)
  {
    readings_[i] = reading;
    if (!was_tracked)
    {
      // Tracked again: the target ramps from where the finger let go (its proxy) to the
      // tracked pose over the soft start, so the proxy gets no step of coupling force.
      render.regrip_from = render.target;
      render.regrip_at = time;
    }
    const double s = softStartScale(time - render.regrip_at, guards_[i].params().soft_start);
    render.target = render.regrip_from + s * (input.target - render.regrip_from);
    render.wall_force = input.wall_force;
    presses_.cycle_model = presses_.cycle_model || (input.pressed & kButtonCycleModel);
    presses_.reset = presses_.reset || (input.pressed & kButtonReset);
    presses_.toggle_stop = presses_.toggle_stop || (input.pressed & kButtonStopForce);
    if (input.orientation == OrientationInput::kUsable)
    {
      frame_.orientations[i] = inputs_[i].worldOrientation();
      frame_.oriented[i] = 1;
    }
    else if (input.orientation == OrientationInput::kRejected)
    {
      // Ignored, counted: the last good orientation stays, and the samples carry it.
      ++counters_->rejected_orientations;
      readings_[i].has_orientation = inputs_[i].oriented();
      readings_[i].orientation = inputs_[i].deviceOrientation();
    }
  }
  else
  {
    ++counters_->rejected_readings;
  }
  render.previous_velocity = render.velocity;
  render.velocity = (render.target - render.previous_target) / dt;
  frame_.targets[i] = render.target;  // always finite
  frame_.velocities[i] = render.velocity;
  frame_.let_go[i] = reading.tracked ? 0 : 1;
}

void HapticSide::decidePending(ServoMailboxes* mail)
{
  const support::RealTimeSection real_time;
  if (!pending_)
  {
    return;
  }
  if (mail->results.take())
  {
    latest_ = mail->results.front();  // same lengths: no allocation
  }
  for (std::size_t i = 0; i < interfaces_.size(); ++i)
  {
    if (!frame_exchange_[i])  // a frame device's force was decided within its exchange
    {
      decideInterface(i, pending_tick_, pending_time_, pending_period_us_);
    }
  }
  pending_ = false;
}

void HapticSide::decideInterface(std::size_t i, long tick, double time, double period_us)
{
  Render& render = render_[i];
  const ProxyResult& proxy = latest_.proxies[i];
  const long lag = tick - latest_.tick;
  // A frame device decides at the read, before the step that takes this reading: the step of
  // the tick before is on time for it. On time it is rendered at the read (the step's proxy,
  // this reading) without the hold's controller, as a packet device's exact force is; late, its
  // hold begins as a packet device's does when it leaves exact mode.
  const bool frame = frame_exchange_[i];
  const long on_time_lag = frame ? 1 : 0;
  const bool held = lag > on_time_lag;
  if (frame && held && !render.frame_held)
  {
    render.multirate.exact = true;  // so that renderMultirate begins the hold here
  }
  render.frame_held = frame && held;
  const MultirateDevice device{render.target, render.previous_target, render.velocity, render.previous_velocity};
  const MultirateStep step{proxy.proxy_position,     proxy.user_force,        lag,
                           proxy.interface_position, proxy.contact_stiffness, proxy.contact_normal,
                           proxy.plane_count,        proxy.plane_normals};
  PassivityController& hold = hold_passivity_[i];
  const double dissipated_before = render.multirate.exact ? 0.0 : hold.dissipated();
  const bool exact = renderMultirate(couplings_[i], recovery_periods_, device, step, &render.multirate,
                                     frame && !held ? nullptr : &hold);
  // Stale: a packet device's force not the step's own (late, or recovering from it); a frame
  // device's rendered from a late step.
  render.stale = frame ? held : !exact;
  render.ready_at = exact ? latest_.done_at : steadySeconds();
  if (render.stale)
  {
    ++counters_->stale_ticks;
  }
  if (!exact && (held || !frame))
  {
    if (hold.damping() > 0.0 || hold.cut() > 0.0)
    {
      ++counters_->hold_damped_ticks;
    }
    counters_->hold_dissipated.store(counters_->hold_dissipated.load() + hold.dissipated() - dissipated_before);
    counters_->hold_lowest_energy.store(std::min(counters_->hold_lowest_energy.load(), hold.lowestEnergy()));
  }
  const Eigen::Vector3d force = render.multirate.force;  // N, world, on the hand
  // The torque: the last completed step's, in the device frame, on the profile's axes only.
  render.torque = renderableTorque(interfaces_[i].profile, interfaces_[i].mapping.torqueToDevice(proxy.user_torque));
  if (!guards_[i].command(time, interfaces_[i].mapping.forceToDevice(force) + render.wall_force))
  {
    ++counters_->rejected_forces;
  }
  if (frame)
  {
    // Applied in this very frame, through the guard as a packet device's is at its next update.
    applied_[i] = guards_[i].output(time);
    applied_torque_[i] = guards_[i].scale(time) * render.torque;
  }
  const double commanded_at = steadySeconds();
  ServoSample* sample = reserveSlot(*samples_, simulated_time_, running_);
  if (!sample)
  {
    ++counters_->dropped_samples;
    return;
  }
  sample->tick = tick;
  sample->time = time;
  sample->interface = static_cast<int>(i);
  sample->reading = readings_[i];
  sample->applied_force = applied_[i];
  sample->applied_torque = applied_torque_[i];
  sample->commanded_force = guards_[i].commanded();
  sample->interface_position = render.target;
  sample->interface_orientation =
      frame_.oriented[i] ? frame_.orientations[i] : Eigen::Quaterniond(Eigen::Quaterniond::Identity());
  sample->proxy_position = proxy.proxy_position;
  sample->user_force = force;
  sample->user_torque = proxy.user_torque;
  sample->commanded_torque = render.torque;
  sample->read_at = read_at_[i];
  sample->period_us = period_us;
  sample->latency_us = 1e6 * ((simulated_time_ ? commanded_at : render.ready_at) - read_at_[i]);
  sample->step_us = latest_.step_us;
  sample->step_profile = latest_.step_profile;
  sample->stale = render.stale;
  sample->physics_lag = lag;
  sample->tracked = render.tracked;
  sample->missing = render.missing;
  samples_->commit();
}
}  // namespace god_finger::internal
