// The delay line as its own process (see god_finger/ros/delay_node.h).
#include "god_finger/ros/delay_node.h"
#include "god_finger/ros/run_node.h"

int main(int argc, char** argv)
{
  return god_finger::runNode<god_finger::DelayNode>(argc, argv, "delay");
}
