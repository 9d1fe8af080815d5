// The servo loop's clock and scheduling, Linux: CLOCK_MONOTONIC seconds, absolute sleeps (no
// drift), SCHED_FIFO and mlockall. Each call is real-time safe except the two set-up calls,
// which are made once when a loop thread starts.
#pragma once

namespace god_finger
{
// Seconds on CLOCK_MONOTONIC (std::chrono::steady_clock's clock on Linux).
double steadySeconds();
// Sleeps until `deadline` (steadySeconds() time), absolute, so that wake-ups do not drift.
void sleepUntil(double deadline);
void sleepFor(double seconds);
// SCHED_FIFO at `priority` (1-99) for the calling thread; false when not permitted or 0.
bool setRealTimePriority(int priority);
// mlockall(current and future); false when not permitted.
bool lockMemory();
}  // namespace god_finger
