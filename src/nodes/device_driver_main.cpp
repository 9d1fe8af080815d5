// The device_driver node as its own process (see god_finger/ros/device_driver_node.h).
#include "god_finger/ros/device_driver_node.h"
#include "god_finger/ros/run_node.h"

int main(int argc, char** argv)
{
  return god_finger::runNode<god_finger::DeviceDriverNode>(argc, argv, "device_driver");
}
