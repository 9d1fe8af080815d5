// The body of every standalone node's main(): ROS set-up, the node, spinning; a bad parameter,
// scene or device stops the process with one line on stderr and exit code 1.
#pragma once

#include <ros/ros.h>

#include <exception>
#include <iostream>

namespace god_finger
{
template <class Node>
int runNode(int argc, char** argv, const char* default_name)
{
  ros::init(argc, argv, default_name);
  try
  {
    ros::NodeHandle nh;
    ros::NodeHandle pnh("~");
    Node node(nh, pnh);
    ros::AsyncSpinner spinner(2);
    spinner.start();
    ros::waitForShutdown();
  }
  catch (const std::exception& error)
  {
    // On stderr directly: rosconsole may not flush before the process ends.
    std::cerr << ros::this_node::getName() << ": " << error.what() << std::endl;
    return 1;
  }
  return 0;
}
}  // namespace god_finger
