#include "god_finger/ros/realtime.h"

#include <ros/console.h>

#include <pthread.h>
#include <sched.h>

#include <cstring>

namespace god_finger
{
bool requestRealTimePriority(int priority, const std::string& who)
{
  if (priority <= 0)
  {
    return false;
  }
  sched_param parameters{};
  parameters.sched_priority = priority;
  const int error = pthread_setschedparam(pthread_self(), SCHED_FIFO, &parameters);
  if (error != 0)
  {
    ROS_WARN(
        "%s: runs without real-time priority (SCHED_FIFO %d: %s); grant CAP_SYS_NICE or an rtprio limit "
        "for steadier 1 kHz timing",
        who.c_str(), priority, std::strerror(error));
    return false;
  }
  ROS_INFO("%s: servo thread at real-time priority %d (SCHED_FIFO)", who.c_str(), priority);
  return true;
}
}  // namespace god_finger
