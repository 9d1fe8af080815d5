// The schedule of a fixed-rate loop: the one rule the servo loop, the physics node and the
// device driver keep their period by. Tick k (0, 1, ...) is due to end at its deadline,
// start + (k + 1) period; the loop sleeps until the deadline when it is on time and starts the
// next tick at once when it is late (an overrun), so a late tick is caught up on the next ones
// and the schedule does not drift. A loop more than kMaxLatePeriods periods behind (a
// debugger, a suspended process) restarts the schedule from the moment it noticed, instead of
// racing through the missed ticks: the next deadline is then one period after that moment.
//
// Units: seconds on any one monotonic clock, passed in (so it runs on simulated time in tests).
// Not thread-safe (one loop thread). Every call is real-time safe (no allocation, lock or log);
// the constructor throws InputError on a period that is not finite and > 0.
#pragma once

namespace god_finger
{
class FixedRateSchedule
{
 public:
  // A loop this many periods behind its deadline restarts its schedule.
  static constexpr double kMaxLatePeriods = 10.0;

  // The first tick starts at `start` and is due at start + period.
  FixedRateSchedule(double period, double start);

  // When the tick under way is due to end (s).
  double deadline() const;
  // The tick under way ended at `now`: returns when the next one starts, deadline() if on
  // time (sleep until it), else `now` (an overrun, counted; see above for far behind).
  double tickEnded(double now);

  double period() const
  {
    return period_;
  }
  long overruns() const
  {
    return overruns_;
  }

 private:
  double period_;   // s
  double epoch_;    // s: start of tick 0, moved when the schedule restarts
  long ticks_ = 0;  // ticks ended since epoch_
  long overruns_ = 0;
};
}  // namespace god_finger
