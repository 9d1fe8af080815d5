// The platform's floor under the servo loop: how late an empty SCHED_FIFO thread wakes from
// the servo clock's absolute 1 ms sleeps (runtime/servo_clock.h), with nothing else to do.
// A servo period can be no steadier than this.
// usage: wakeup_latency [SECONDS]   prints one JSON line: wake-ups, p50 / p99 / max lateness (us)
#include "god_finger/runtime/servo_clock.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

int main(int argc, char** argv)
{
  using namespace god_finger;
  const double seconds = argc > 1 ? std::atof(argv[1]) : 30.0;
  const bool realtime = setRealTimePriority(80);
  lockMemory();
  const long ticks = static_cast<long>(seconds * 1000.0);
  std::vector<double> late_us(static_cast<std::size_t>(ticks));
  const double start = steadySeconds();
  for (long k = 1; k <= ticks; ++k)
  {
    const double deadline = start + k * 1e-3;
    sleepUntil(deadline);
    late_us[static_cast<std::size_t>(k - 1)] = 1e6 * (steadySeconds() - deadline);
  }
  std::sort(late_us.begin(), late_us.end());
  std::printf(
      "{\"wakeups\": %ld, \"realtime\": %s, \"late_us_p50\": %.1f, \"late_us_p99\": %.1f, \"late_us_max\": %.1f}\n",
      ticks, realtime ? "true" : "false", late_us[late_us.size() / 2], late_us[late_us.size() * 99 / 100],
      late_us.back());
  return 0;
}
