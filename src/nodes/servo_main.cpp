// The servo node as its own process (see god_finger/ros/servo_node.h).
#include "god_finger/ros/servo_node.h"
#include "god_finger/ros/run_node.h"

int main(int argc, char** argv)
{
  return god_finger::runNode<god_finger::ServoNode>(argc, argv, "servo");
}
