#include "god_finger/runtime/servo_loop.h"

#include "god_finger/core/input_error.h"
#include "god_finger/runtime/servo_clock.h"

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
}  // namespace

ServoLoop::ServoLoop(std::unique_ptr<GodFingerWorld> world, std::vector<ServoInterface> interfaces,
                     const ServoLoopParams& params, Log log)
    : world_(std::move(world)),
      interfaces_(std::move(interfaces)),
      params_(checked(params)),
      log_(std::move(log)),
      buttons_(interfaces_.size(), 0u),
      readings_(interfaces_.size()),
      applied_(interfaces_.size(), Eigen::Vector3d::Zero()),
      read_at_(interfaces_.size(), 0.0),
      samples_(static_cast<std::size_t>(params.queue_ticks) * std::max<std::size_t>(1, interfaces_.size())),
      snapshots_(4),
      commands_(64)
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
  for (const ServoInterface& interface : interfaces_)
  {
    if (!interface.device)
    {
      throw InputError("interface '" + interface.name + "' has no device");
    }
    guards_.emplace_back(interface.profile.guard);
  }
}

ServoLoop::~ServoLoop()
{
  stop();
}

void ServoLoop::prepare()
{
  if (prepared_)
  {
    return;
  }
  for (std::size_t i = 0; i < interfaces_.size(); ++i)
  {
    ServoInterface& interface = interfaces_[i];
    interface.device->start();
    readings_[i] = interface.device->update(0.0, Eigen::Vector3d::Zero());
    const Eigen::Vector3d start = interface.mapping.toWorld(readings_[i].position);
    if (!start.allFinite())
    {
      throw DeviceError("interface '" + interface.name + "': the device's first position is not finite");
    }
    world_->addInterface(start, interface.profile.coupling);
  }
  // Every snapshot slot sized once (the ring has capacity + 1 slots: one push and pop each
  // moves on by one), so that tick() never allocates for them.
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
  else if (command.kind == ServoCommand::Kind::kHandTarget &&
           (command.interface < 0 || command.interface >= static_cast<int>(interfaces_.size()) ||
            !command.hand_target.allFinite()))
  {
    why = "hand target for no interface, or not finite";
  }
  if (why.empty())
  {
    std::lock_guard<std::mutex> lock(post_mutex_);
    if (!commands_.tryPush(command))
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

void ServoLoop::applyCommands()
{
  ServoCommand command;
  while (commands_.tryPop(&command))
  {
    ++counters_.commands;
    switch (command.kind)
    {
      case ServoCommand::Kind::kSetContactModel:
        world_->setContactModel(command.model);
        break;
      case ServoCommand::Kind::kSetContactParams:
        world_->setContactParams(command.contact);  // validated by post()
        break;
      case ServoCommand::Kind::kReset:
        world_->resetAtInterfaces();
        break;
      case ServoCommand::Kind::kHandTarget:
        interfaces_[command.interface].device->setHandTarget(command.hand_target);
        break;
    }
  }
  counters_.model = static_cast<int>(world_->contactModel());
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

void ServoLoop::tick(double time)
{
  const double start = steadySeconds();
  const double period_us = last_tick_start_ < 0.0 ? 1e6 / params_.rate : 1e6 * (start - last_tick_start_);
  last_tick_start_ = start;
  bool cycle_model = false;
  bool reset = false;
  for (std::size_t i = 0; i < interfaces_.size(); ++i)
  {
    ServoInterface& interface = interfaces_[i];
    applied_[i] = guards_[i].output(time);
    readings_[i] = interface.device->update(time, applied_[i]);
    read_at_[i] = steadySeconds();
    const std::uint32_t pressed = readings_[i].buttons & ~buttons_[i];
    buttons_[i] = readings_[i].buttons;
    cycle_model = cycle_model || (pressed & 1u);
    reset = reset || (pressed & 2u);
    const Eigen::Vector3d target = interface.mapping.toWorld(readings_[i].position);
    if (!target.allFinite())
    {
      ++counters_.rejected_readings;
    }
    world_->setInterfaceTarget(static_cast<int>(i), target);
  }
  applyCommands();
  if (cycle_model)
  {
    world_->setContactModel(nextContactModel(world_->contactModel()));
    counters_.model = static_cast<int>(world_->contactModel());
  }
  if (reset)
  {
    world_->resetAtInterfaces();
  }
  const double step_start = steadySeconds();
  world_->step();
  const double step_end = steadySeconds();
  for (std::size_t i = 0; i < interfaces_.size(); ++i)
  {
    const InterfaceState& state = world_->interfaceState(static_cast<int>(i));
    const Eigen::Vector3d force = interfaces_[i].mapping.forceToDevice(state.user_force);
    if (!guards_[i].command(time, force))
    {
      ++counters_.rejected_forces;
    }
    const double commanded_at = steadySeconds();
    ServoSample* sample = reserveIn(samples_);
    if (!sample)
    {
      ++counters_.dropped_samples;
      continue;
    }
    sample->tick = tick_;
    sample->time = time;
    sample->interface = static_cast<int>(i);
    sample->reading = readings_[i];
    sample->applied_force = applied_[i];
    sample->commanded_force = guards_[i].output(time);
    sample->interface_position = state.interface_position;
    sample->proxy_position = state.proxy_position;
    sample->user_force = state.user_force;
    sample->read_at = read_at_[i];
    sample->period_us = period_us;
    sample->latency_us = 1e6 * (commanded_at - read_at_[i]);
    sample->step_us = 1e6 * (step_end - step_start);
    samples_.commit();
  }
  if (tick_ % params_.snapshot_every == 0)
  {
    WorldSnapshot* slot = reserveIn(snapshots_);
    if (slot)
    {
      world_->snapshot(slot);
      snapshots_.commit();
    }
    else
    {
      ++counters_.dropped_snapshots;
    }
  }
  ++tick_;
  ++counters_.ticks;
}

void ServoLoop::run()
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
  double epoch = steadySeconds();
  long scheduled = 0;  // ticks since epoch
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
    const double deadline = epoch + scheduled * period / pace;
    const double now = steadySeconds();
    if (now > deadline)
    {
      ++counters_.overruns;
      if (now - deadline > 10.0 * period / pace)
      {
        // Far behind (a debugger, a suspended process): restart the schedule instead of racing.
        epoch = now - scheduled * period / pace;
      }
      continue;
    }
    sleepUntil(deadline);
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
