// The servo loop a servo node runs, built from its parameters (servo_node.h lists them): the
// one place that turns a launch's parameters into a ServoLoop, so that a test or a tool can
// build the very loop a launch runs and step it offline (on simulated time the two give the
// same trajectory bit for bit).
#pragma once

#include "god_finger/physics/world_params.h"
#include "god_finger/runtime/servo_loop.h"

#include <ros/node_handle.h>

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

namespace god_finger
{
struct ServoSetup
{
  std::unique_ptr<ServoLoop> loop;  // prepared (devices started, proxies placed)
  WorldParams world_params;
  std::string scene_path;
  std::vector<std::string> names;            // interfaces (a hand's: one per finger, NAME/FINGER), in the loop's order
  std::vector<std::string> backends;         // their backend names
  std::vector<bool> hand_targets;            // backends moved by a dragged hand (an rviz marker)
  std::vector<Eigen::Vector3d> hand_starts;  // their marker's start (m, device frame)
};

// `nh`: the namespace the interfaces live under; `pnh`: the servo's private parameters.
// Throws InputError / DeviceError.
ServoSetup makeServoSetup(const ros::NodeHandle& nh, const ros::NodeHandle& pnh, ServoLoop::Log log = ServoLoop::Log());
}  // namespace god_finger
