// Simulated time's physics (runtime/servo_loop.h): in lockstep with the haptic side, each tick's
// targets stepped within that tick, except the steps the test seam (ServoLoopParams::
// physics_delay) makes late by whole periods, deterministically: the step that takes tick k's
// targets completes at tick k + d (its result reaches the haptic side then), and the physics
// takes no targets meanwhile; at tick k + d the late step completes first, then tick k + d's
// targets are stepped (or held, when late too). No delay function: every step on time.
//
// Thread: the loop's (tick()'s caller), between the haptic side's targets and its decision.
// Meets both sides only through servo_mailboxes.h: it takes the targets box and steps
// PhysicsSide into the results box. Real-time safe as far as PhysicsSide::step and the delay
// function are (the held frame is sized at construction).
#pragma once

#include "physics_side.h"
#include "servo_mailboxes.h"

#include <functional>

namespace god_finger::internal
{
class PhysicsDelaySeam
{
 public:
  // `delay`: periods late for the step taking tick k's targets, called once per step taken.
  // `sized`: a frame of the loop's length.
  PhysicsDelaySeam(std::function<int(long tick)> delay, const TargetFrame& sized);

  // This tick: the targets the haptic side just posted to `mail`, stepped or held.
  void tick(PhysicsSide* physics, ServoMailboxes* mail);

 private:
  void step(PhysicsSide* physics, const TargetFrame& frame, ServoMailboxes* mail);

  std::function<int(long tick)> delay_;
  TargetFrame held_;  // the targets of the late step in progress
  bool busy_ = false;
  long ready_tick_ = 0;  // the tick at which it completes
};
}  // namespace god_finger::internal
