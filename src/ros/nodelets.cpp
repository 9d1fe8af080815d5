// The nodes as nodelets (one manager, zero-copy messages between them). A bad
// parameter, scene or device makes the nodelet fail to load with the node's one-line message.
#include "god_finger/ros/delay_node.h"
#include "god_finger/ros/device_driver_node.h"
#include "god_finger/ros/haptic_node.h"
#include "god_finger/ros/physics_node.h"
#include "god_finger/ros/servo_node.h"

#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include <memory>
#include <stdexcept>

namespace god_finger
{
template <class Node>
class NodeletOf : public nodelet::Nodelet
{
 private:
  void onInit() override
  {
    try
    {
      node_ = std::make_unique<Node>(getMTNodeHandle(), getMTPrivateNodeHandle());
    }
    catch (const std::exception& error)
    {
      NODELET_FATAL("%s: %s", getName().c_str(), error.what());
      throw std::runtime_error(error.what());
    }
  }
  std::unique_ptr<Node> node_;
};

class PhysicsNodelet : public NodeletOf<PhysicsNode>
{
};
class HapticNodelet : public NodeletOf<HapticNode>
{
};
class DeviceDriverNodelet : public NodeletOf<DeviceDriverNode>
{
};
class ServoNodelet : public NodeletOf<ServoNode>
{
};
class DelayNodelet : public NodeletOf<DelayNode>
{
};
}  // namespace god_finger

PLUGINLIB_EXPORT_CLASS(god_finger::PhysicsNodelet, nodelet::Nodelet)
PLUGINLIB_EXPORT_CLASS(god_finger::HapticNodelet, nodelet::Nodelet)
PLUGINLIB_EXPORT_CLASS(god_finger::DeviceDriverNodelet, nodelet::Nodelet)
PLUGINLIB_EXPORT_CLASS(god_finger::ServoNodelet, nodelet::Nodelet)
PLUGINLIB_EXPORT_CLASS(god_finger::DelayNodelet, nodelet::Nodelet)
