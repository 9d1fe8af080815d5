// The platform's floor for the servo-loop benchmarks (hand_loop_bench, soft_loop_bench): the
// periods (us) of an empty SCHED_FIFO thread's absolute 1 ms wake-ups over `seconds`, measured
// in the same run as the loop they are compared with (as bench/wakeup_latency.cpp); and the
// percentile the benchmarks report (the nearest rank below q of the sorted values).
#pragma once

#include "god_finger/runtime/servo_clock.h"

#include <algorithm>
#include <thread>
#include <vector>

namespace god_finger
{
inline double benchPercentile(std::vector<double> values, double q)
{
  std::sort(values.begin(), values.end());
  return values.empty() ? 0.0 : values[static_cast<std::size_t>(q * (values.size() - 1))];
}

inline std::vector<double> floorPeriods(double seconds)
{
  std::vector<double> periods;
  std::thread thread(
      [&periods, seconds]()
      {
        setRealTimePriority(80);
        const long ticks = static_cast<long>(seconds * 1000.0);
        periods.reserve(static_cast<std::size_t>(ticks));
        const double start = steadySeconds();
        double last = start;
        for (long k = 1; k <= ticks; ++k)
        {
          sleepUntil(start + k * 1e-3);
          const double now = steadySeconds();
          periods.push_back(1e6 * (now - last));
          last = now;
        }
      });
  thread.join();
  return periods;
}
}  // namespace god_finger
