// One node's port of the haptic <-> physics channel across processes (issue 29): the two-port
// observer and the physics side's controller of haptics/two_port_passivity.h as the topic
// topologies run them.
//  - The haptic node's device port (observer only) counts the work the hand does through the
//    rendered force (DeviceState: -applied_force . velocity over the time between states, in the
//    world's power, WorkspaceMapping::powerToWorld; the workspace wall this node adds is not the
//    channel's and is left out); it sends its packet on NAME/device_energy with every state. Its
//    controller is the device driver's (haptics/passivity_controller.h).
//  - The physics node's physics port (PhysicsPortPassivity: answer()) takes the position a pose
//    gave, counts the spring the step before holds for it (runtime/multirate_render.h heldForce
//    at rest: what the haptic node's local coupling renders, no force in free space; the
//    coupling's damper only dissipates, and is left out) over its moves, and
//    with passivity_damping_limit > 0 (the device profile's, as the driver's) pulls the position
//    the world is given back out of a contact by what the device's energy and the contact's
//    credit do not cover; it sends its packet on NAME/physics_energy with every step.
// Each keeps the other's newest figure (a late, lost or reordered packet leaves an older, smaller
// one: the margin stays conservative on any link) and reports on /diagnostics (addValues):
//   channel_energy_in_J, channel_energy_out_J   this port's counts (J, world power)
//   channel_remote_energy_in_J                  the other port's E_in as received (J)
//   channel_margin_J, channel_lowest_margin_J   remote E_in - own E_out, now and its lowest
//   channel_packets, channel_rejected_packets   received, and refused (non-finite or negative)
//   channel_drift_m, channel_controlled_steps   the physics port's: the position's drift now,
//                                               the steps its controller acted at
// The channel is passive when both ports' margins stay >= 0 (the physics port's >= -credit).
// Threads: every call takes the port's own lock (callbacks of any thread). Not real-time: it
// publishes.
#pragma once

#include "god_finger/PortEnergy.h"
#include "god_finger/haptics/two_port_passivity.h"

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <ros/ros.h>

#include <memory>
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
  // An observed port: sends on `send_topic`, receives from `receive_topic` (both resolved in
  // `nh`); the session starts now.
  ChannelPort(ros::NodeHandle nh, const std::string& send_topic, const std::string& receive_topic);
  // The physics port with its controller, answering once every `period` s; InputError on bad
  // parameters or period.
  ChannelPort(ros::NodeHandle nh, const std::string& send_topic, const std::string& receive_topic,
              const PassivityParams& params, double period);
  // An observed port's: `work` J through the port since the last call (> 0 into the channel),
  // counted at `stamp`; sends the packet.
  void observeWork(double work, const ros::Time& stamp);
  // The physics port's (PhysicsPortPassivity::answer): the position to give the world for the
  // one seen, and the force `force_at` gives there. Publishes nothing (called under the world's
  // lock): sendPacket() does.
  template <class ForceAt>
  Eigen::Vector3d answer(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity, ForceAt&& force_at,
                         Eigen::Vector3d* used_position, Eigen::Vector3d* used_velocity)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return controller_->answer(position, velocity, force_at, used_position, used_velocity);
  }
  // The physics port's packet of what it counted so far, stamped `stamp`.
  void sendPacket(const ros::Time& stamp);
  // The physics port's controller made anew with `params` (the device's profile read again),
  // before it first answered: its counts restart, the other side's figure is taken again from
  // its next packet. InputError on bad parameters.
  void reconfigure(const PassivityParams& params, double period);
  bool controlled() const
  {
    return controller_ != nullptr;
  }
  void addValues(diagnostic_msgs::DiagnosticStatus* status) const;
  PortSide port() const;  // a copy of the side's figures, under the lock

 private:
  void onPacket(const god_finger::PortEnergy::ConstPtr& message);
  PortSide& side()
  {
    return controller_ ? static_cast<PortSide&>(*controller_) : port_;
  }
  const PortSide& side() const
  {
    return controller_ ? static_cast<const PortSide&>(*controller_) : port_;
  }

  mutable std::mutex mutex_;
  ObservedPort port_;
  std::unique_ptr<PhysicsPortPassivity> controller_;  // the physics port's, or none
  long rejected_ = 0;
  ros::Time session_;
  ros::Publisher publisher_;
  ros::Subscriber subscriber_;
};
}  // namespace god_finger
