// The ROS side of the driver bridges (devices/driver_bridge.h): for one backend it
//  - subscribes to the driver's own state (and button) topics, in the driver's message types,
//    and writes each state into the DriverLink, stamped on steadySeconds()' clock at arrival;
//  - publishes the forces the device leaves in the link, in the driver's force type (every field
//    the driver reads filled), from a sender thread of its own;
//  - sends a zero force when it goes, and on a signal (zero_on_stop.h), and only zeros from then;
//  - reports on /diagnostics, once a second: the driver's measured rate, the age of its newest
//    state, whether anything takes the force; ERROR naming the topic when the driver is stale.
// The topics, their types, the frame and units each driver uses: driverWires(), one row a
// backend (docs/devices.md prints it).
// Threads: the subscriptions' callbacks run on the node's spinner; the sender and the
// diagnostics' timer are not real-time; nothing here is called from the device loop.
#pragma once

#include "god_finger/devices/driver_bridge.h"

#include <ros/node_handle.h>

#include <memory>
#include <string>
#include <vector>

namespace god_finger
{
struct DriverWire
{
  const char* backend;      // the device registry's name
  const char* driver;       // the driver as users know it, and its repository
  const char* state_topic;  // relative to driver_ns (an absolute one stays as it is)
  const char* state_type;
  const char* buttons;  // the button topics and how they map to god_finger's buttons
  const char* force_topic;
  const char* force_type;
};
const std::vector<DriverWire>& driverWires();
const DriverWire& driverWire(const std::string& backend);

// `nh`: the interface's namespace (for the throttled log's name); `node_name` starts the
// diagnostics' status names. The handle keeps everything alive; dropping it sends a zero. Store
// it in link->connection: it keeps a plain pointer to `link`, which must outlive it.
std::shared_ptr<void> connectDriverLink(ros::NodeHandle nh, const std::string& node_name,
                                        const DriverBridgeParams& params, std::shared_ptr<DriverLink> link);
}  // namespace god_finger
