// god_finger_delay: a network link made in user space between two nodes (issue 29), for testing
// a set-up across machines with a real network's delay, jitter and loss. It relays one topic of
// any message type, `in` to `out` (remap them: `in:=/finger/pose out:=/finger/pose_delayed`),
// each message leaving when runtime/delay_line.h's schedule says, on the ROS clock: on simulated
// time a run repeats exactly. Released by a 1 kHz timer (so up to 1 ms more than the schedule).
//
// Parameters (private, delayLineParameterTable()): delay (s), jitter (s), loss, reorder, seed.
// Diagnostics (/diagnostics, 1 Hz), "delay: IN -> OUT": the messages that entered and were lost,
// those in flight, and the mean delay of those released in the last second.
// Errors: a bad parameter stops the node with one line (InputError).
#pragma once

#include <ros/ros.h>

#include <memory>

namespace god_finger
{
class DelayNode
{
 public:
  DelayNode(ros::NodeHandle nh, ros::NodeHandle pnh);
  ~DelayNode();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
}  // namespace god_finger
