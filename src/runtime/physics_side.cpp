#include "physics_side.h"

#include "god_finger/runtime/servo_clock.h"
#include "god_finger/support/contract.h"
#include "god_finger/support/denormals.h"
#include "god_finger/support/input_error.h"

#include <algorithm>

namespace god_finger::internal
{
namespace
{
// The commands whose application rebuilds Bullet's world (a reset) or edits it (a spawn, a
// delete), and so allocates, on this thread.
bool rebuildsTheWorld(ServoCommand::Kind kind)
{
  return kind == ServoCommand::Kind::kReset || kind == ServoCommand::Kind::kAddObject ||
         kind == ServoCommand::Kind::kRemoveObject;
}
}  // namespace

PhysicsSide::PhysicsSide(std::unique_ptr<GodFingerWorld> world, const ServoLoopParams& params, std::size_t interfaces,
                         ServoCounters* counters, SpscQueue<ServoCommand>* commands,
                         SpscQueue<WorldSnapshot>* snapshots, const std::atomic<bool>& running)
    : world_(std::move(world)),
      rate_(params.rate),
      snapshot_every_(params.snapshot_every),
      simulated_time_(params.simulated_time),
      realtime_priority_(params.realtime_priority),
      interfaces_(interfaces),
      counters_(counters),
      commands_(commands),
      snapshots_(snapshots),
      running_(running)
{
  counters_->model = static_cast<int>(world_->contactModel());
  counters_->pad_solver = static_cast<int>(world_->params().pad_solver);
}

CouplingProfile PhysicsSide::addInterface(const std::string& name, const Eigen::Vector3d& start,
                                          const CouplingProfile& coupling)
{
  try
  {
    // Refused when the hand starts inside a body (GodFingerWorld::addInterface): the loop does
    // not start, with the interface, the body and the position named.
    const int index = world_->addInterface(start, coupling);
    return world_->coupling(index);
  }
  catch (const InputError& error)
  {
    throw InputError("interface '" + name + "': " + error.what());
  }
}

void PhysicsSide::prepare()
{
  // The ring has capacity + 1 slots: one push and pop each moves on by one.
  WorldSnapshot sized;
  world_->snapshot(&sized);
  WorldSnapshot drained;
  for (std::size_t i = 0; i <= snapshots_->capacity(); ++i)
  {
    *snapshots_->reserve() = sized;
    snapshots_->commit();
    const bool popped = snapshots_->tryPop(&drained);
    GOD_FINGER_EXPECTS(popped, "the element just committed comes out");
  }
  counters_->model = static_cast<int>(world_->contactModel());
}

void PhysicsSide::setTargets(const TargetFrame& frame)
{
  const bool consecutive = frame.tick == last_frame_tick_ + 1;
  counters_->skipped_targets += consecutive ? 0 : frame.tick - last_frame_tick_ - 1;
  for (std::size_t i = 0; i < interfaces_; ++i)
  {
    const int interface = static_cast<int>(i);
    const bool by_difference = consecutive && !frame.let_go[i];
    if (by_difference && frame.oriented[i])
    {
      world_->setInterfaceTarget(interface, frame.targets[i], frame.orientations[i]);
    }
    else if (by_difference)
    {
      world_->setInterfaceTarget(interface, frame.targets[i]);
    }
    else
    {
      // The skipped ticks' motion is not one step's: a free proxy is carried across it (less the
      // one step's motion the coupling makes), and the damping takes the device's velocity (a
      // let-go finger's: zero; the rotational coupling's takes the orientation's change over the
      // skipped ticks).
      if (!consecutive && !frame.let_go[i] && frame.targets[i].allFinite() && frame.velocities[i].allFinite())
      {
        const Eigen::Vector3d skipped =
            frame.targets[i] - world_->interfaceState(interface).interface_position - frame.velocities[i] / rate_;
        world_->carryFreeProxy(interface, skipped);
      }
      world_->setInterfaceTarget(interface, frame.targets[i], frame.velocities[i]);
      if (frame.oriented[i])
      {
        world_->setInterfaceTarget(interface, frame.targets[i], frame.orientations[i]);
      }
    }
  }
  last_frame_tick_ = frame.tick;
}

void PhysicsSide::applyCommands()
{
  ServoCommand command;
  while (commands_->tryPop(&command))
  {
    ++counters_->commands;
    counters_->world_rebuilds += rebuildsTheWorld(command.kind) ? 1 : 0;
    applyWorldCommand(command, world_.get());  // validated by post(); others are never queued here
  }
  counters_->model = static_cast<int>(world_->contactModel());
  counters_->pad_solver = static_cast<int>(world_->params().pad_solver);
}

void PhysicsSide::applyPresses(const TargetFrame& frame)
{
  if (frame.cycle_presses > seen_cycle_presses_)
  {
    for (long n = seen_cycle_presses_; n < frame.cycle_presses; ++n)
    {
      world_->setContactModel(nextContactModel(world_->contactModel()));
    }
    seen_cycle_presses_ = frame.cycle_presses;
    counters_->model = static_cast<int>(world_->contactModel());
  }
  if (frame.reset_presses > seen_reset_presses_)
  {
    seen_reset_presses_ = frame.reset_presses;
    ++counters_->world_rebuilds;
    world_->resetAtInterfaces();
  }
}

void PhysicsSide::step(const TargetFrame& frame, StepResult* out)
{
  setTargets(frame);
  const long steps_before = world_->steps();
  applyCommands();
  applyPresses(frame);
  if (world_->steps() < steps_before)  // reset: the world's time starts again from 0
  {
    world_time_offset_ = frame.time;
  }
  const double step_start = steadySeconds();
  world_->step();
  const double step_end = steadySeconds();
  ++counters_->physics_steps;
  out->tick = frame.tick;
  out->done_at = step_end;
  out->step_us = 1e6 * (step_end - step_start);
  out->step_profile = world_->stepProfile();
  for (std::size_t i = 0; i < interfaces_; ++i)
  {
    const InterfaceState& state = world_->interfaceState(static_cast<int>(i));
    ProxyResult& proxy = out->proxies[i];
    proxy.proxy_position = state.proxy_position;
    proxy.user_force = state.user_force;
    proxy.user_torque = state.user_torque;
    proxy.interface_position = state.interface_position;
    proxy.contact_stiffness = state.contact_stiffness;
    proxy.contact_normal = state.contact_normal;
    proxy.plane_count = std::min(state.contact_count, MultirateStep::kMaxPlanes);
    for (int c = 0; c < proxy.plane_count; ++c)
    {
      proxy.plane_normals[c] = state.contacts[c].normal;
    }
  }
  snapshotIfDue(frame.tick);
}

void PhysicsSide::snapshotIfDue(long tick)
{
  if (tick < next_snapshot_tick_)
  {
    return;
  }
  next_snapshot_tick_ = (tick / snapshot_every_ + 1) * snapshot_every_;
  WorldSnapshot* slot = reserveSlot(*snapshots_, simulated_time_, running_);
  if (!slot)
  {
    ++counters_->dropped_snapshots;
    return;
  }
  world_->snapshot(slot);
  slot->time += world_time_offset_;  // on the loop's clock (ServoLoop::snapshots())
  snapshots_->commit();
}

bool PhysicsSide::run(ServoMailboxes* mail, const std::atomic<bool>& keep_running, std::string* error)
{
  flushDenormalsInThisThread();  // support/denormals.h
  setRealTimePriority(realtime_priority_ > 1 ? realtime_priority_ - 1 : 0);
  while (keep_running)
  {
    mail->wake.wait();  // at least every 20 ms: keep_running is looked at that often
    if (!mail->targets.take())
    {
      continue;  // woken for targets already stepped (posts accumulate while a step runs)
    }
    try
    {
      step(mail->targets.front(), &mail->results.back());
      mail->results.publish();
    }
    catch (const std::exception& thrown)
    {
      *error = thrown.what();
      return false;
    }
  }
  return true;
}
}  // namespace god_finger::internal
