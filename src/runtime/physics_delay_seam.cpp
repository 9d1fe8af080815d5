#include "physics_delay_seam.h"

namespace god_finger::internal
{
PhysicsDelaySeam::PhysicsDelaySeam(std::function<int(long tick)> delay, const TargetFrame& sized)
    : delay_(std::move(delay)), held_(sized)
{
}

void PhysicsDelaySeam::step(PhysicsSide* physics, const TargetFrame& frame, ServoMailboxes* mail)
{
  physics->step(frame, &mail->results.back());
  mail->results.publish();
}

void PhysicsDelaySeam::tick(PhysicsSide* physics, ServoMailboxes* mail)
{
  mail->targets.take();  // in lockstep: this tick's, always fresh
  const TargetFrame& targets = mail->targets.front();
  if (busy_ && ready_tick_ <= targets.tick)
  {
    // The late step completes now, with the targets it took when it began.
    step(physics, held_, mail);
    busy_ = false;
  }
  if (busy_)
  {
    return;
  }
  const int delay = delay_ ? delay_(targets.tick) : 0;
  if (delay <= 0)
  {
    step(physics, targets, mail);
    return;
  }
  held_ = targets;
  ready_tick_ = targets.tick + delay;
  busy_ = true;
}
}  // namespace god_finger::internal
