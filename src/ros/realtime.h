// Real-time scheduling for a servo thread (the device driver's 1 kHz loop): SCHED_FIFO at the
// given priority (1-99; 0 leaves the thread as it is). Without the right (CAP_SYS_NICE, or
// `rtprio` in /etc/security/limits.conf) the thread keeps normal scheduling and one warning
// says so. Returns whether the priority was set.
#pragma once

#include <string>

namespace god_finger
{
bool requestRealTimePriority(int priority, const std::string& who);
}  // namespace god_finger
