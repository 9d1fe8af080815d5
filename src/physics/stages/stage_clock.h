// Times the stages of one world step into a StepProfile (god_finger/physics/step_profile.h): each
// mark() gives the time since the previous mark (or start()) to a stage. Internal to physics.
//
// Cost: one steady_clock read per mark (about 24 ns with the TSC clocksource; eleven a step) on
// a timed step, one branch per mark on the others. Real-time safe: no allocation, no lock.
#pragma once

#include "god_finger/physics/step_profile.h"

#include <chrono>

namespace god_finger::internal
{
class StageClock
{
 public:
  explicit StageClock(StepProfile* profile) : profile_(profile) {}
  // Starts a step, timed or not (an untimed step's marks and finish do nothing, the profile keeps
  // the last timed step's): a timed one's stages restart at zero.
  void start(bool timed)
  {
    timed_ = timed;
    if (!timed_)
    {
      return;
    }
    profile_->stage_ns.fill(0);
    profile_->total_ns = 0;
    begin_ = last_ = Clock::now();
  }
  // The time since the last mark goes to `stage` (added: a stage may be marked twice).
  void mark(StepStage stage)
  {
    if (!timed_)
    {
      return;
    }
    const Clock::time_point now = Clock::now();
    profile_->stage_ns[static_cast<int>(stage)] +=
        std::chrono::duration_cast<std::chrono::nanoseconds>(now - last_).count();
    last_ = now;
  }
  // Ends the step `step` (the world's step count after it): total_ns from start() to the last mark.
  void finish(long step)
  {
    if (!timed_)
    {
      return;
    }
    profile_->step = step;
    profile_->total_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(last_ - begin_).count();
  }

 private:
  using Clock = std::chrono::steady_clock;
  StepProfile* profile_;
  bool timed_ = false;
  Clock::time_point begin_;
  Clock::time_point last_;
};
}  // namespace god_finger::internal
