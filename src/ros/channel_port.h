// One node's port of the haptic <-> physics channel across processes (issue 29): the two-port
// observer of haptics/two_port_passivity.h (ObservedPort) as the topic topologies run it.
//  - The haptic node's device port counts the work the hand does through the rendered force
//    (DeviceState: -applied_force . velocity over the time between states, in the world's power,
//    WorkspaceMapping::powerToWorld; the workspace wall this node adds is not the channel's and is
//    left out); it sends its packet on NAME/device_energy with every state.
//  - The physics node's physics port counts the work of the force it answers with over the move
//    of the position it was given (InterfaceState::user_force . (target_k - target_k-1)) and
//    sends its packet on NAME/physics_energy with every step.
// Each keeps the other's newest figure (a late, lost or reordered packet leaves an older, smaller
// one: the margin stays conservative on any link) and reports on /diagnostics (addValues):
//   channel_energy_in_J, channel_energy_out_J   this port's counts (J, world power)
//   channel_remote_energy_in_J                  the other port's E_in as received (J)
//   channel_margin_J, channel_lowest_margin_J   remote E_in - own E_out, now and its lowest
//   channel_packets, channel_rejected_packets   received, and refused (non-finite or negative)
// The channel is passive when both ports' margins stay >= 0. Observer only: the controller that
// keeps the hand's side passive is the device driver's (haptics/passivity_controller.h); why the
// physics port's controller is not on by default: docs/decisions.md.
// Threads: every call takes the port's own lock (callbacks of any thread). Not real-time: it
// publishes.
#pragma once

#include "god_finger/PortEnergy.h"
#include "god_finger/haptics/two_port_passivity.h"

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <ros/ros.h>

#include <mutex>
#include <string>

namespace god_finger
{
// The packet as the message carries it, counted since `session`.
god_finger::PortEnergy portEnergyMessage(const ros::Time& stamp, const ros::Time& session,
                                         const PortEnergyObserver& observer);
// The message as a packet and its session (s); false, outputs untouched, for a non-finite or
// negative energy or stamp.
bool energyPacket(const god_finger::PortEnergy& message, EnergyPacket* packet, double* session);

class ChannelPort
{
 public:
  ChannelPort() = default;
  // Sends on `send_topic`, receives from `receive_topic` (both resolved in `nh`); the session
  // starts now.
  ChannelPort(ros::NodeHandle nh, const std::string& send_topic, const std::string& receive_topic);
  // `work` J through the port since the last call (> 0 into the channel), counted at `stamp`;
  // sends the packet.
  void observeWork(double work, const ros::Time& stamp);
  void addValues(diagnostic_msgs::DiagnosticStatus* status) const;
  ObservedPort port() const;  // a copy, under the lock

 private:
  void onPacket(const god_finger::PortEnergy::ConstPtr& message);

  mutable std::mutex mutex_;
  ObservedPort port_;
  long rejected_ = 0;
  ros::Time session_;
  ros::Publisher publisher_;
  ros::Subscriber subscriber_;
};
}  // namespace god_finger
