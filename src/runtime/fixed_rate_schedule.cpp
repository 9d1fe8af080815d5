#include "god_finger/runtime/fixed_rate_schedule.h"

#include "god_finger/support/input_error.h"

#include <cmath>
#include <string>

namespace god_finger
{
FixedRateSchedule::FixedRateSchedule(double period, double start) : period_(period), epoch_(start)
{
  if (!(std::isfinite(period) && period > 0.0))
  {
    throw InputError("a fixed-rate loop's period must be finite and > 0 (s), not " + std::to_string(period));
  }
  if (!std::isfinite(start))
  {
    throw InputError("a fixed-rate loop's start time must be finite (s)");
  }
}

double FixedRateSchedule::deadline() const
{
  // From the epoch, not summed period by period, so that rounding does not drift.
  return epoch_ + static_cast<double>(ticks_ + 1) * period_;
}

double FixedRateSchedule::tickEnded(double now)
{
  const double due = deadline();
  ++ticks_;
  if (now <= due)
  {
    return due;
  }
  ++overruns_;
  if (now - due > kMaxLatePeriods * period_)
  {
    epoch_ = now - static_cast<double>(ticks_) * period_;  // the next tick starts now
  }
  return now;
}
}  // namespace god_finger
