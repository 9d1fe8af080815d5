#include "realtime.h"

#include <ros/console.h>

#include "god_finger/runtime/servo_clock.h"

namespace god_finger
{
bool requestRealTimePriority(int priority, const std::string& who)
{
  if (priority <= 0)
  {
    return false;
  }
  if (!setRealTimePriority(priority))
  {
    ROS_WARN(
        "%s: runs without real-time priority (SCHED_FIFO %d not permitted); grant CAP_SYS_NICE or an rtprio limit "
        "for steadier 1 kHz timing",
        who.c_str(), priority);
    return false;
  }
  ROS_INFO("%s: servo thread at real-time priority %d (SCHED_FIFO)", who.c_str(), priority);
  return true;
}
}  // namespace god_finger
