#include "god_finger/runtime/servo_loop.h"
#include "god_finger/runtime/multirate_render.h"

#include "god_finger/haptics/interface_input.h"
#include "god_finger/haptics/workspace_bound.h"
#include "god_finger/runtime/fixed_rate_schedule.h"
#include "god_finger/runtime/servo_clock.h"
#include "god_finger/support/denormals.h"
#include "god_finger/support/input_error.h"

#include <cmath>
#include <sstream>

namespace god_finger
{
const ParameterTable<ServoLoopParams>& servoLoopParameterTable()
{
  using P = ServoLoopParams;
  static const ParameterTable<P> table = {
      realRow<P>("rate", "Hz", closed(10.0, 10000.0),
                 "the servo loop's (and the device's) rate; the world steps at 1 / rate",
                 [](P& p) -> double& { return p.rate; }),
      integerRow<P>("realtime_priority", closed(0, 99),
                    "SCHED_FIFO priority of the loop's thread, 0 for normal scheduling",
                    [](P& p) -> int& { return p.realtime_priority; }),
      realRow<P>("real_time_factor", "dimensionless", closed(0.0, 1000.0),
                 "simulated time only: simulated seconds per wall second, 0 as fast as it goes",
                 [](P& p) -> double& { return p.real_time_factor; }),
      integerRow<P>("snapshot_every", closed(1, 1000000),
                    "ticks between world snapshots for the publishers (the servo node sets it from publish_rate)",
                    [](P& p) -> int& { return p.snapshot_every; }),
      integerRow<P>("queue_ticks", closed(16, 1000000), "ticks of samples the publishers may lag behind",
                    [](P& p) -> int& { return p.queue_ticks; }),
  };
  return table;
}

std::string validate(const ServoLoopParams& params)
{
  return validateRows(servoLoopParameterTable(), params);
}

namespace
{
const ServoLoopParams& checked(const ServoLoopParams& params)
{
  const std::string error = validate(params);
  if (!error.empty())
  {
    throw InputError(error);
  }
  return params;
}

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

ServoLoop::ServoLoop(std::unique_ptr<GodFingerWorld> world, std::vector<ServoInterface> interfaces,
                     const ServoLoopParams& params, Log log)
    : world_(std::move(world)),
      interfaces_(std::move(interfaces)),
      params_(checked(params)),
      log_(std::move(log)),
      readings_(interfaces_.size()),
      applied_(interfaces_.size(), Eigen::Vector3d::Zero()),
      applied_torque_(interfaces_.size(), Eigen::Vector3d::Zero()),
      read_at_(interfaces_.size(), 0.0),
      render_(interfaces_.size()),
      samples_(static_cast<std::size_t>(params.queue_ticks) * std::max<std::size_t>(1, interfaces_.size())),
      snapshots_(4),
      commands_(64),
      hand_commands_(64)
{
  if (!world_ || interfaces_.empty())
  {
    throw InputError("the servo loop needs a world and at least one interface");
  }
  if (std::abs(world_->params().time_step * params_.rate - 1.0) > 1e-9)
  {
    std::ostringstream message;
    message << "the world's time step " << world_->params().time_step << " s is not one servo period (1 / "
            << params_.rate << " Hz)";
    throw InputError(message.str());
  }
  if (params_.recovery_periods < 1)
  {
    throw InputError("the servo loop's recovery_periods must be at least 1");
  }
  if (params_.physics_delay && !params_.simulated_time)
  {
    throw InputError("the servo loop's physics_delay test seam works on simulated time only");
  }
  for (const ServoInterface& interface : interfaces_)
  {
    if (!interface.device)
    {
      throw InputError("interface '" + interface.name + "' has no device");
    }
    guards_.emplace_back(interface.profile.coupling.max_force, interface.profile.guard);
    hold_passivity_.emplace_back(interface.profile.passivity, 1.0 / params_.rate);
    inputs_.emplace_back(interface.profile, interface.mapping);
    frame_exchange_.push_back(interface.device->exchangeForm() == DeviceExchange::kFrame ? 1 : 0);
  }
  counters_.model = static_cast<int>(world_->contactModel());
  counters_.pad_solver = static_cast<int>(world_->params().pad_solver);
  sem_init(&physics_wake_, 0, 0);
}

ServoLoop::~ServoLoop()
{
  stop();
  sem_destroy(&physics_wake_);
}

void ServoLoop::prepare()
{
  if (prepared_)
  {
    return;
  }
  const std::size_t n = interfaces_.size();
  latest_.proxies.resize(n);
  frame_.targets.resize(n);
  frame_.velocities.resize(n, Eigen::Vector3d::Zero());
  frame_.let_go.resize(n, 0);
  frame_.orientations.resize(n, Eigen::Quaterniond::Identity());
  frame_.oriented.resize(n, 0);
  for (std::size_t i = 0; i < n; ++i)
  {
    ServoInterface& interface = interfaces_[i];
    interface.device->start();
    readings_[i] = interface.device->update(0.0, Eigen::Vector3d::Zero());
    // Within the workspace (haptics/workspace_bound.h), as every later reading.
    const Eigen::Vector3d start = interface.mapping.toWorld(
        boundToWorkspace(readings_[i].position, interface.profile, interface.mapping).position);
    if (!start.allFinite())
    {
      throw DeviceError("interface '" + interface.name + "': the device's first position is not finite");
    }
    if (!readings_[i].velocity.allFinite())
    {
      readings_[i].velocity.setZero();  // the samples carry finite readings only
    }
    try
    {
      // Refused when the hand starts inside a body (GodFingerWorld::addInterface): the loop does
      // not start, with the interface, the body and the position named.
      world_->addInterface(start, interface.profile.coupling);
    }
    catch (const InputError& error)
    {
      throw InputError("interface '" + interface.name + "': " + error.what());
    }
    couplings_.push_back(world_->coupling(static_cast<int>(i)));
    Render& render = render_[i];
    render.target = render.previous_target = render.multirate.anchor = start;
    latest_.proxies[i].proxy_position = start;
    frame_.targets[i] = start;
  }
  seam_frame_ = frame_;
  seam_result_ = latest_;
  if (!params_.simulated_time)
  {
    targets_box_ = std::make_unique<LatestValue<TargetFrame>>(frame_);
    results_box_ = std::make_unique<LatestValue<StepResult>>(latest_);
  }
  // Every snapshot slot sized once (the ring has capacity + 1 slots: one push and pop each
  // moves on by one), so that neither side ever allocates for them.
  WorldSnapshot sized;
  world_->snapshot(&sized);
  WorldSnapshot drained;
  for (std::size_t i = 0; i <= snapshots_.capacity(); ++i)
  {
    *snapshots_.reserve() = sized;
    snapshots_.commit();
    snapshots_.tryPop(&drained);
  }
  counters_.model = static_cast<int>(world_->contactModel());
  prepared_ = true;
}

bool ServoLoop::post(const ServoCommand& command, std::string* error)
{
  std::string why;
  if (command.kind == ServoCommand::Kind::kSetContactParams)
  {
    why = validate(command.contact);
  }
  else if (command.kind == ServoCommand::Kind::kSetPadSolver && command.pad_solver != PadSolver::kPoints &&
           command.pad_solver != PadSolver::kConstraint)
  {
    why = "pad solver " + std::to_string(static_cast<int>(command.pad_solver)) + " is not one of " + padSolverNames();
  }
  else if ((command.kind == ServoCommand::Kind::kAddObject || command.kind == ServoCommand::Kind::kRemoveObject) &&
           (!command.edit || (command.kind == ServoCommand::Kind::kAddObject && !command.edit->object)))
  {
    why = "an object edit without its object";
  }
  else if (command.kind == ServoCommand::Kind::kHandTarget &&
           (command.interface < 0 || command.interface >= static_cast<int>(interfaces_.size()) ||
            !command.hand_target.allFinite()))
  {
    why = "hand target for no interface, or not finite";
  }
  if (why.empty())
  {
    std::lock_guard<std::mutex> lock(post_mutex_);
    const bool haptic_side = command.kind == ServoCommand::Kind::kHandTarget ||
                             command.kind == ServoCommand::Kind::kStopForce ||
                             command.kind == ServoCommand::Kind::kResumeForce;
    SpscQueue<ServoCommand>& queue = haptic_side ? hand_commands_ : commands_;
    if (!queue.tryPush(command))
    {
      why = "the servo loop's command queue is full";
    }
  }
  if (error)
  {
    *error = why;
  }
  return why.empty();
}

void ServoLoop::applyHandTargets(double time)
{
  ServoCommand command;
  while (hand_commands_.tryPop(&command))
  {
    ++counters_.commands;
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
    else if (command.hand_oriented)
    {
      interfaces_[command.interface].device->setHandPose(command.hand_target, command.hand_orientation);
    }
    else
    {
      interfaces_[command.interface].device->setHandTarget(command.hand_target);
    }
  }
  counters_.force_stopped = !guards_.empty() && guards_[0].stopped();
}

void ServoLoop::applyWorldCommands()
{
  ServoCommand command;
  while (commands_.tryPop(&command))
  {
    ++counters_.commands;
    applyWorldCommand(command, world_.get());  // validated by post(); others are never queued here
  }
  counters_.model = static_cast<int>(world_->contactModel());
  counters_.pad_solver = static_cast<int>(world_->params().pad_solver);
}

template <class T>
T* ServoLoop::reserveIn(SpscQueue<T>& queue)
{
  T* slot = queue.reserve();
  // Simulated time: the publishers get everything; the loop waits for them instead.
  while (!slot && params_.simulated_time && running_)
  {
    sleepFor(100e-6);
    slot = queue.reserve();
  }
  return slot;
}

// A kFrame device's responder: the reading in, this tick's force for it out, within the frame.
class ServoLoop::FrameStep : public FrameResponder
{
 public:
  FrameStep(ServoLoop* loop, std::size_t interface, double time, double period_us, Presses* presses)
      : loop_(loop), interface_(interface), time_(time), period_us_(period_us), presses_(presses)
  {
  }
  void respond(const DeviceReading& reading, Eigen::Vector3d* force, Eigen::Vector3d* torque) override
  {
    loop_->takeReading(interface_, reading, time_, presses_);
    loop_->decideInterface(interface_, loop_->tick_, time_, period_us_);
    *force = loop_->applied_[interface_];
    *torque = loop_->applied_torque_[interface_];
  }

 private:
  ServoLoop* loop_;
  std::size_t interface_;
  double time_;
  double period_us_;
  Presses* presses_;
};

void ServoLoop::readDevices(double time, double period_us)
{
  Presses presses;
  for (std::size_t i = 0; i < interfaces_.size(); ++i)
  {
    ServoInterface& interface = interfaces_[i];
    if (frame_exchange_[i])
    {
      FrameStep step(this, i, time, period_us, &presses);
      interface.device->exchangeFrame(time, step);
      continue;
    }
    applied_[i] = guards_[i].output(time);
    // The torque decided for the last reading (zero for a device with no torque axes), through
    // the force's guard: its soft start and watchdog ramp, zero while the force is stopped.
    applied_torque_[i] = guards_[i].scale(time) * render_[i].torque;
    const DeviceReading reading = interface.device->updateWrench(time, applied_[i], applied_torque_[i]);
    takeReading(i, reading, time, &presses);
  }
  if (presses.toggle_stop)  // button 2: stop every device's force, or resume it (soft start)
  {
    const bool stop = !guards_.empty() && !guards_[0].stopped();
    for (ForceGuard& guard : guards_)
    {
      stop ? guard.stop() : guard.resume(time);
    }
    counters_.force_stopped = stop;
  }
  cycle_presses_ += presses.cycle_model ? 1 : 0;
  reset_presses_ += presses.reset ? 1 : 0;
  frame_.tick = tick_;
  frame_.time = time;
  frame_.read_at = read_at_[0];
  frame_.cycle_presses = cycle_presses_;
  frame_.reset_presses = reset_presses_;
}

void ServoLoop::takeReading(std::size_t i, const DeviceReading& reading, double time, Presses* presses)
{
  const double dt = 1.0 / params_.rate;
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
    ++counters_.untracked_readings;
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
    presses->cycle_model = presses->cycle_model || (input.pressed & kButtonCycleModel);
    presses->reset = presses->reset || (input.pressed & kButtonReset);
    presses->toggle_stop = presses->toggle_stop || (input.pressed & kButtonStopForce);
    if (input.orientation == OrientationInput::kUsable)
    {
      frame_.orientations[i] = inputs_[i].worldOrientation();
      frame_.oriented[i] = 1;
    }
    else if (input.orientation == OrientationInput::kRejected)
    {
      // Ignored, counted: the last good orientation stays, and the samples carry it.
      ++counters_.rejected_orientations;
      readings_[i].has_orientation = inputs_[i].oriented();
      readings_[i].orientation = inputs_[i].deviceOrientation();
    }
  }
  else
  {
    ++counters_.rejected_readings;
  }
  render.previous_velocity = render.velocity;
  render.velocity = (render.target - render.previous_target) / dt;
  frame_.targets[i] = render.target;  // always finite
  frame_.velocities[i] = render.velocity;
  frame_.let_go[i] = reading.tracked ? 0 : 1;
}

void ServoLoop::stepFrame(const TargetFrame& frame, StepResult* out)
{
  const bool consecutive = frame.tick == last_frame_tick_ + 1;
  counters_.skipped_targets += consecutive ? 0 : frame.tick - last_frame_tick_ - 1;
  for (std::size_t i = 0; i < interfaces_.size(); ++i)
  {
    const bool by_difference = consecutive && !frame.let_go[i];
    if (by_difference && frame.oriented[i])
    {
      world_->setInterfaceTarget(static_cast<int>(i), frame.targets[i], frame.orientations[i]);
    }
    else if (by_difference)
    {
      world_->setInterfaceTarget(static_cast<int>(i), frame.targets[i]);
    }
    else
    {
      // The skipped ticks' motion is not one step's: a free proxy is carried across it (less the
      // one step's motion the coupling makes), and the damping takes the device's velocity (a
      // let-go finger's: zero; the rotational coupling's takes the orientation's change over the
      // skipped ticks).
      if (!consecutive && !frame.let_go[i] && frame.targets[i].allFinite() && frame.velocities[i].allFinite())
      {
        const Eigen::Vector3d skipped = frame.targets[i] -
                                        world_->interfaceState(static_cast<int>(i)).interface_position -
                                        frame.velocities[i] / params_.rate;
        world_->carryFreeProxy(static_cast<int>(i), skipped);
      }
      world_->setInterfaceTarget(static_cast<int>(i), frame.targets[i], frame.velocities[i]);
      if (frame.oriented[i])
      {
        world_->setInterfaceTarget(static_cast<int>(i), frame.targets[i], frame.orientations[i]);
      }
    }
  }
  last_frame_tick_ = frame.tick;
  const long steps_before = world_->steps();
  applyWorldCommands();
  if (frame.cycle_presses > seen_cycle_presses_)
  {
    for (long n = seen_cycle_presses_; n < frame.cycle_presses; ++n)
    {
      world_->setContactModel(nextContactModel(world_->contactModel()));
    }
    seen_cycle_presses_ = frame.cycle_presses;
    counters_.model = static_cast<int>(world_->contactModel());
  }
  if (frame.reset_presses > seen_reset_presses_)
  {
    seen_reset_presses_ = frame.reset_presses;
    world_->resetAtInterfaces();
  }
  if (world_->steps() < steps_before)  // reset: the world's time starts again from 0
  {
    world_time_offset_ = frame.time;
  }
  const double step_start = steadySeconds();
  world_->step();
  const double step_end = steadySeconds();
  ++counters_.physics_steps;
  out->tick = frame.tick;
  out->done_at = step_end;
  out->step_us = 1e6 * (step_end - step_start);
  out->step_profile = world_->stepProfile();
  for (std::size_t i = 0; i < interfaces_.size(); ++i)
  {
    const InterfaceState& state = world_->interfaceState(static_cast<int>(i));
    out->proxies[i].proxy_position = state.proxy_position;
    out->proxies[i].user_force = state.user_force;
    out->proxies[i].user_torque = state.user_torque;
    out->proxies[i].interface_position = state.interface_position;
    out->proxies[i].contact_stiffness = state.contact_stiffness;
    out->proxies[i].contact_normal = state.contact_normal;
    out->proxies[i].plane_count = std::min(state.contact_count, MultirateStep::kMaxPlanes);
    for (int c = 0; c < out->proxies[i].plane_count; ++c)
    {
      out->proxies[i].plane_normals[c] = state.contacts[c].normal;
    }
  }
  if (frame.tick >= next_snapshot_tick_)
  {
    next_snapshot_tick_ = (frame.tick / params_.snapshot_every + 1) * params_.snapshot_every;
    WorldSnapshot* slot = reserveIn(snapshots_);
    if (slot)
    {
      world_->snapshot(slot);
      slot->time += world_time_offset_;  // on the loop's clock (snapshots())
      snapshots_.commit();
    }
    else
    {
      ++counters_.dropped_snapshots;
    }
  }
}

void ServoLoop::physicsInline()
{
  if (seam_busy_ && seam_ready_tick_ <= tick_)
  {
    // The late step completes now, with the targets it took when it began.
    stepFrame(seam_frame_, &latest_);
    seam_busy_ = false;
  }
  if (seam_busy_)
  {
    return;
  }
  const int delay = params_.physics_delay ? params_.physics_delay(tick_) : 0;
  if (delay <= 0)
  {
    stepFrame(frame_, &latest_);
    return;
  }
  seam_frame_ = frame_;
  seam_ready_tick_ = tick_ + delay;
  seam_busy_ = true;
}

void ServoLoop::decide(long tick, double time, double period_us)
{
  for (std::size_t i = 0; i < interfaces_.size(); ++i)
  {
    if (!frame_exchange_[i])  // a frame device's force was decided within its exchange
    {
      decideInterface(i, tick, time, period_us);
    }
  }
}

void ServoLoop::decideInterface(std::size_t i, long tick, double time, double period_us)
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
  const bool exact = renderMultirate(couplings_[i], params_.recovery_periods, device, step, &render.multirate,
                                     frame && !held ? nullptr : &hold);
  // Stale: a packet device's force not the step's own (late, or recovering from it); a frame
  // device's rendered from a late step.
  render.stale = frame ? held : !exact;
  render.ready_at = exact ? latest_.done_at : steadySeconds();
  if (render.stale)
  {
    ++counters_.stale_ticks;
  }
  if (!exact && (held || !frame))
  {
    if (hold.damping() > 0.0 || hold.cut() > 0.0)
    {
      ++counters_.hold_damped_ticks;
    }
    counters_.hold_dissipated.store(counters_.hold_dissipated.load() + hold.dissipated() - dissipated_before);
    counters_.hold_lowest_energy.store(std::min(counters_.hold_lowest_energy.load(), hold.lowestEnergy()));
  }
  const Eigen::Vector3d force = render.multirate.force;  // N, world, on the hand
  // The torque: the last completed step's, in the device frame, on the profile's axes only.
  render.torque = renderableTorque(interfaces_[i].profile, interfaces_[i].mapping.torqueToDevice(proxy.user_torque));
  if (!guards_[i].command(time, interfaces_[i].mapping.forceToDevice(force) + render.wall_force))
  {
    ++counters_.rejected_forces;
  }
  if (frame_exchange_[i])
  {
    // Applied in this very frame, through the guard as a packet device's is at its next update.
    applied_[i] = guards_[i].output(time);
    applied_torque_[i] = guards_[i].scale(time) * render.torque;
  }
  const double commanded_at = steadySeconds();
  ServoSample* sample = reserveIn(samples_);
  if (!sample)
  {
    ++counters_.dropped_samples;
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
  sample->latency_us = 1e6 * ((params_.simulated_time ? commanded_at : render.ready_at) - read_at_[i]);
  sample->step_us = latest_.step_us;
  sample->step_profile = latest_.step_profile;
  sample->stale = render.stale;
  sample->physics_lag = lag;
  sample->tracked = render.tracked;
  sample->missing = render.missing;
  samples_.commit();
}

void ServoLoop::tick(double time)
{
  const double start = steadySeconds();
  const double period_us = last_tick_start_ < 0.0 ? 1e6 / params_.rate : 1e6 * (start - last_tick_start_);
  last_tick_start_ = start;
  if (!params_.simulated_time)
  {
    // The force for the previous tick's reading, from whatever step completed by now; the
    // update below applies it. Never waits for the physics.
    if (pending_)
    {
      if (results_box_->take())
      {
        latest_.tick = results_box_->front().tick;
        latest_.done_at = results_box_->front().done_at;
        latest_.step_us = results_box_->front().step_us;
        latest_.step_profile = results_box_->front().step_profile;
        latest_.proxies = results_box_->front().proxies;  // same length: no allocation
      }
      decide(tick_ - 1, pending_time_, pending_period_us_);
      pending_ = false;
    }
    readDevices(time, period_us);
    applyHandTargets(time);
    targets_box_->back() = frame_;  // same lengths: no allocation
    targets_box_->publish();
    sem_post(&physics_wake_);
    pending_ = true;
    pending_time_ = time;
    pending_period_us_ = period_us;
  }
  else
  {
    readDevices(time, period_us);
    applyHandTargets(time);
    physicsInline();
    decide(tick_, time, period_us);
  }
  ++tick_;
  ++counters_.ticks;
}

void ServoLoop::runPhysics()
{
  flushDenormalsInThisThread();  // support/denormals.h
  const int priority = params_.realtime_priority > 1 ? params_.realtime_priority - 1 : 0;
  setRealTimePriority(priority);
  StepResult* out = nullptr;
  while (physics_running_)
  {
    timespec deadline;
    clock_gettime(CLOCK_REALTIME, &deadline);
    deadline.tv_nsec += 20000000;  // 20 ms: looks at physics_running_ at least that often
    if (deadline.tv_nsec >= 1000000000)
    {
      deadline.tv_nsec -= 1000000000;
      ++deadline.tv_sec;
    }
    sem_timedwait(&physics_wake_, &deadline);
    if (!targets_box_->take())
    {
      continue;  // woken for targets already stepped (posts accumulate while a step runs)
    }
    try
    {
      out = &results_box_->back();
      stepFrame(targets_box_->front(), out);
      results_box_->publish();
    }
    catch (const std::exception& error)
    {
      counters_.failed = true;
      running_ = false;
      physics_running_ = false;
      if (log_)
      {
        log_(std::string("servo loop's physics stopped: ") + error.what());
      }
      return;
    }
  }
}

void ServoLoop::run()
{
  flushDenormalsInThisThread();  // support/denormals.h: this thread and, on simulated time, its physics
  if (!params_.simulated_time)
  {
    physics_running_ = true;
    physics_thread_ = std::thread([this]() { runPhysics(); });
  }
  runTicks();
  if (physics_thread_.joinable())
  {
    physics_running_ = false;
    sem_post(&physics_wake_);
    physics_thread_.join();
  }
  if (pending_)
  {
    // The last tick's force (and sample), from the physics as it stopped.
    if (results_box_->take())
    {
      latest_ = results_box_->front();
    }
    decide(tick_ - 1, pending_time_, pending_period_us_);
    pending_ = false;
  }
}

void ServoLoop::runTicks()
{
  // On simulated time nothing is gained by real-time priority, and a loop that runs as fast
  // as it goes must not starve the publishers it waits for.
  const int priority = params_.simulated_time ? 0 : params_.realtime_priority;
  const bool realtime = setRealTimePriority(priority);
  counters_.realtime = realtime;
  if (!realtime && priority > 0 && log_)
  {
    log_("servo loop: runs without real-time priority (SCHED_FIFO " + std::to_string(params_.realtime_priority) +
         " not permitted): grant CAP_SYS_NICE or an rtprio limit for steadier 1 kHz timing");
  }
  if (params_.lock_memory && !params_.simulated_time && !lockMemory() && log_)
  {
    log_("servo loop: memory not locked (mlockall not permitted): a page fault can stall a tick");
  }
  const double period = 1.0 / params_.rate;
  const double pace = params_.simulated_time ? params_.real_time_factor : 1.0;
  // On the wall clock at `pace` (none when pace <= 0: as fast as it goes).
  FixedRateSchedule schedule(pace > 0.0 ? period / pace : period, steadySeconds());
  long scheduled = 0;                                       // ticks since the start
  const long earlier_overruns = counters_.overruns.load();  // of an earlier start()
  while (running_)
  {
    try
    {
      // The period's nominal time: exact on simulated time, the schedule's on the wall clock
      // (devices estimate velocities from it, so it must not jitter).
      tick(static_cast<double>(params_.simulated_time ? tick_ : scheduled) * period);
    }
    catch (const std::exception& error)
    {
      counters_.failed = true;
      running_ = false;
      if (log_)
      {
        log_(std::string("servo loop stopped: ") + error.what());
      }
      return;
    }
    catch (...)
    {
      counters_.failed = true;
      running_ = false;
      if (log_)
      {
        log_("servo loop stopped: unknown exception");
      }
      return;
    }
    ++scheduled;
    if (pace <= 0.0)
    {
      continue;
    }
    const double now = steadySeconds();
    const double next = schedule.tickEnded(now);
    counters_.overruns.store(earlier_overruns + schedule.overruns());
    if (next > now)
    {
      sleepUntil(next);
    }
  }
}

void ServoLoop::start()
{
  if (running_)
  {
    return;
  }
  if (thread_.joinable())
  {
    thread_.join();  // a loop that stopped by itself (a device failed)
  }
  prepare();
  running_ = true;
  thread_ = std::thread([this]() { run(); });
}

void ServoLoop::stop()
{
  running_ = false;
  if (thread_.joinable())
  {
    thread_.join();
  }
}

bool ServoLoop::running() const
{
  return running_;
}
}  // namespace god_finger
