// The last force a held-force driver gets from this process is zero (devices/driver_bridge.h):
// the ROS drivers labs run (omni_common, ros_geomagic, the CRTK saw components, ros_falcon)
// render the last force they were sent forever. A normal stop sends the zero from the bridge's
// destructor; this hook covers the stops that never reach it:
//  - SIGINT (Ctrl-C of a launch, roslaunch's first signal), SIGTERM, SIGHUP: roscpp would shut
//    its connections down first. The hook sends every registered zero, then hands the signal on
//    to the handler that was there before (roscpp's: ros::requestShutdown()).
//  - SIGSEGV, SIGBUS, SIGFPE, SIGABRT (a crash of the physics in the same process): the zeros are
//    sent from the hook's thread while the crashing one waits for them (at most 0.2 s), then the
//    signal takes its default course (the core dump, the exit code).
// Installed once per process, at the first registration (after ros::init: its handler is the
// one handed on); the zeros are written (waitForPublishes) before it. Threads: register/unregister from any thread; the
// zeros are sent from the hook's own thread, never from the signal handler (only async-signal-safe calls there).
#pragma once

#include <functional>

namespace god_finger
{
// roscpp writes a message published from another thread in its poll thread, later: a publisher
// dropped (or a shutdown) right after publish() can lose it. This waits until the poll thread has
// made two whole passes since the call (the write of everything published before it was tried),
// at most `timeout` s; false on time-out (no poll thread: roscpp shut down). Not real-time.
bool waitForPublishes(double timeout);

// `send_zero` publishes a zero force (and, from then on, only zeros); called at most once per
// signal, from the hook's thread. The id unregisters it (before its publisher goes).
int registerZeroOnStop(std::function<void()> send_zero);
void unregisterZeroOnStop(int id);
}  // namespace god_finger
