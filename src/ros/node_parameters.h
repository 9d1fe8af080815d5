// The ROS nodes' own parameters (publishing, scripts, timeouts) in one table, and the loop's
// timing read from the servo loop's table (runtime/servo_loop.h): every node that reads one of
// them reads it from here, with one default and one range. Not real-time (read at start).
#pragma once

#include "god_finger/support/parameter_table.h"
#include "god_finger/runtime/servo_loop.h"

#include <ros/node_handle.h>

namespace god_finger
{
struct NodeParams
{
  double publish_rate = 60.0;    // Hz: markers, TF of the bodies, contact areas, diagnostics
  double script_delay = 2.0;     // s: simulated devices start their scripts this long after the launch
  double proxy_timeout = 0.25;   // s: the haptic node stops rendering a proxy older than this
  int wait_for_subscribers = 0;  // sim_time: the servo waits for this many subscribers of device/state
};

// publish_rate, script_delay, proxy_timeout, wait_for_subscribers.
const ParameterTable<NodeParams>& nodeParameterTable();

// Every row set in the node's private namespace; InputError naming the first bad one.
NodeParams readNodeParams(const ros::NodeHandle& pnh);
// The servo loop's rows (rate, realtime_priority, real_time_factor, ...) set there.
ServoLoopParams readLoopParams(const ros::NodeHandle& pnh);
}  // namespace god_finger
