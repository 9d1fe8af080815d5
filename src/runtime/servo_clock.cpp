#include "god_finger/runtime/servo_clock.h"

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <time.h>

#include <cerrno>
#include <cmath>

namespace god_finger
{
namespace
{
timespec toTimespec(double seconds)
{
  timespec result;
  result.tv_sec = static_cast<time_t>(std::floor(seconds));
  result.tv_nsec = static_cast<long>((seconds - std::floor(seconds)) * 1e9);
  if (result.tv_nsec >= 1000000000L)
  {
    ++result.tv_sec;
    result.tv_nsec -= 1000000000L;
  }
  return result;
}
}  // namespace

double steadySeconds()
{
  timespec now;
  clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

void sleepUntil(double deadline)
{
  const timespec until = toTimespec(deadline);
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &until, nullptr) == EINTR)
  {
  }
}

void sleepFor(double seconds)
{
  sleepUntil(steadySeconds() + seconds);
}

bool setRealTimePriority(int priority)
{
  if (priority <= 0)
  {
    return false;
  }
  sched_param parameters{};
  parameters.sched_priority = priority;
  return pthread_setschedparam(pthread_self(), SCHED_FIFO, &parameters) == 0;
}

bool lockMemory()
{
  return mlockall(MCL_CURRENT | MCL_FUTURE) == 0;
}
}  // namespace god_finger
