#include "god_finger/runtime/servo_loop.h"

#include "haptic_side.h"
#include "physics_delay_seam.h"
#include "physics_side.h"
#include "servo_mailboxes.h"

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

}  // namespace

ServoLoop::ServoLoop(std::unique_ptr<GodFingerWorld> world, std::vector<ServoInterface> interfaces,
                     const ServoLoopParams& params, Log log)
    : params_(checked(params)),
      log_(std::move(log)),
      samples_(static_cast<std::size_t>(params.queue_ticks) * std::max<std::size_t>(1, interfaces.size())),
      snapshots_(4),
      commands_(64),
      hand_commands_(64)
{
  if (!world || interfaces.empty())
  {
    throw InputError("the servo loop needs a world and at least one interface");
  }
  if (std::abs(world->params().time_step * params_.rate - 1.0) > 1e-9)
  {
    std::ostringstream message;
    message << "the world's time step " << world->params().time_step << " s is not one servo period (1 / "
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
  for (const ServoInterface& interface : interfaces)
  {
    if (!interface.device)
    {
      throw InputError("interface '" + interface.name + "' has no device");
    }
  }
  const std::size_t n = interfaces.size();
  physics_ = std::make_unique<internal::PhysicsSide>(std::move(world), params_, n, &counters_, &commands_, &snapshots_,
                                                     running_);
  haptic_ = std::make_unique<internal::HapticSide>(std::move(interfaces), params_, &counters_, &hand_commands_,
                                                   &samples_, running_);
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
  // The one time the two sides meet outside the mailboxes: each device's first reading places
  // its proxy, and the world's coupling for it is the one the haptic side renders.
  for (std::size_t i = 0; i < haptic_->interfaces().size(); ++i)
  {
    const ServoInterface& interface = haptic_->interfaces()[i];
    const Eigen::Vector3d start = haptic_->startDevice(i);
    haptic_->placeInterface(i, start, physics_->addInterface(interface.name, start, interface.profile.coupling));
  }
  mail_ = std::make_unique<internal::ServoMailboxes>(haptic_->targets(), haptic_->latest());
  if (params_.simulated_time)
  {
    seam_ = std::make_unique<internal::PhysicsDelaySeam>(params_.physics_delay, haptic_->targets());
  }
  physics_->prepare();
  prepared_ = true;
}

const GodFingerWorld& ServoLoop::world() const
{
  return physics_->world();
}

const std::vector<ServoInterface>& ServoLoop::interfaces() const
{
  return haptic_->interfaces();
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
           (command.interface < 0 || command.interface >= static_cast<int>(interfaces().size()) ||
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

void ServoLoop::tick(double time)
{
  const double start = steadySeconds();
  const double period_us = last_tick_start_ < 0.0 ? 1e6 / params_.rate : 1e6 * (start - last_tick_start_);
  last_tick_start_ = start;
  if (!params_.simulated_time)
  {
    // The force for the previous tick's reading, from whatever step completed by now; this
    // tick's exchange applies it. Never waits for the physics.
    haptic_->decidePending(mail_.get());
    haptic_->exchange(tick_, time, period_us, mail_.get());
    mail_->wake.post();
  }
  else
  {
    haptic_->exchange(tick_, time, period_us, mail_.get());
    seam_->tick(physics_.get(), mail_.get());
    haptic_->decidePending(mail_.get());
  }
  ++tick_;
  ++counters_.ticks;
}

void ServoLoop::run()
{
  flushDenormalsInThisThread();  // support/denormals.h: this thread and, on simulated time, its physics
  if (!params_.simulated_time)
  {
    physics_running_ = true;
    physics_thread_ = std::thread(
        [this]()
        {
          std::string error;
          if (!physics_->run(mail_.get(), physics_running_, &error))
          {
            counters_.failed = true;
            running_ = false;
            physics_running_ = false;
            if (log_)
            {
              log_("servo loop's physics stopped: " + error);
            }
          }
        });
  }
  runTicks();
  if (physics_thread_.joinable())
  {
    physics_running_ = false;
    mail_->wake.post();
    physics_thread_.join();
  }
  if (!params_.simulated_time)
  {
    haptic_->decidePending(mail_.get());  // the last tick's force (and sample), from the physics as it stopped
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
