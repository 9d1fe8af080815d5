#include "channel_port.h"

#include "diagnostics.h"
#include "god_finger/support/text_numbers.h"
#include "queues.h"

#include <cmath>

namespace god_finger
{
god_finger::PortEnergy portEnergyMessage(const ros::Time& stamp, const ros::Time& session,
                                         const PortEnergyObserver& observer)
{
  god_finger::PortEnergy message;
  message.header.stamp = stamp;
  message.header.frame_id = "world";
  message.energy_in = observer.in();
  message.energy_out = observer.out();
  message.session = session;
  return message;
}

bool energyPacket(const god_finger::PortEnergy& message, EnergyPacket* packet, double* session)
{
  const double stamp = message.header.stamp.toSec();
  if (!std::isfinite(message.energy_in) || !std::isfinite(message.energy_out) || message.energy_in < 0.0 ||
      message.energy_out < 0.0 || !std::isfinite(stamp))
  {
    return false;
  }
  packet->stamp = stamp;
  packet->energy_in = message.energy_in;
  *session = message.session.toSec();
  return true;
}

ChannelPort::ChannelPort(ros::NodeHandle nh, const std::string& send_topic, const std::string& receive_topic)
    : session_(ros::Time::now())
{
  publisher_ = nh.advertise<god_finger::PortEnergy>(send_topic, kPublisherQueue);
  subscriber_ =
      nh.subscribe(receive_topic, kSubscriberQueue, &ChannelPort::onPacket, this, ros::TransportHints().tcpNoDelay());
}

ChannelPort::ChannelPort(ros::NodeHandle nh, const std::string& send_topic, const std::string& receive_topic,
                         const PassivityParams& params, double period)
    : ChannelPort(nh, send_topic, receive_topic)
{
  controller_ = std::make_unique<PhysicsPortPassivity>(params, period);
}

void ChannelPort::sendPacket(const ros::Time& stamp)
{
  god_finger::PortEnergy message;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    message = portEnergyMessage(stamp, session_, side().observer());
  }
  publisher_.publish(message);
}

void ChannelPort::reconfigure(const PassivityParams& params, double period)
{
  auto controller = std::make_unique<PhysicsPortPassivity>(params, period);
  std::lock_guard<std::mutex> lock(mutex_);
  controller_ = std::move(controller);
}

void ChannelPort::observeWork(double work, const ros::Time& stamp)
{
  god_finger::PortEnergy message;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    port_.observeWork(work);
    message = portEnergyMessage(stamp, session_, port_.observer());
  }
  publisher_.publish(message);
}

void ChannelPort::onPacket(const god_finger::PortEnergy::ConstPtr& message)
{
  EnergyPacket packet;
  double session = 0.0;
  const bool good = energyPacket(*message, &packet, &session);
  std::lock_guard<std::mutex> lock(mutex_);
  if (!good)
  {
    ++rejected_;
    ROS_WARN_THROTTLE(1.0, "channel: rejected a malformed port energy packet (%ld so far)", rejected_);
    return;
  }
  side().receive(packet, session);
}

void ChannelPort::addValues(diagnostic_msgs::DiagnosticStatus* status) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  const PortSide& counted = side();
  addValue(status, "channel_energy_in_J", jsonNumber(counted.observer().in()));
  addValue(status, "channel_energy_out_J", jsonNumber(counted.observer().out()));
  addValue(status, "channel_remote_energy_in_J", jsonNumber(counted.remote().energyIn()));
  addValue(status, "channel_margin_J", jsonNumber(counted.margin()));
  addValue(status, "channel_lowest_margin_J", jsonNumber(counted.lowestMargin()));
  addValue(status, "channel_packets", std::to_string(counted.packets()));
  addValue(status, "channel_rejected_packets", std::to_string(rejected_));
  if (controller_)
  {
    addValue(status, "channel_drift_m", jsonNumber(controller_->drift().norm()));
    addValue(status, "channel_controlled_steps", std::to_string(controller_->activeTicks()));
  }
}

PortSide ChannelPort::port() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return side();
}
}  // namespace god_finger
