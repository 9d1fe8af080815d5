#!/usr/bin/python3
"""rostest: the docs' ROS commands (docs/demo.md, docs/nodes.md) run, as a user runs them, against the demo: `rostopic echo
-n 1 /tf` (which needs the Python module of tf2_msgs) and `rosservice call /reset_scene` (which
needs std_srvs'): scripts/setup installs both. Each command exits 0 and prints what a user
expects. Nothing sleeps to synchronise: each waits on its condition, with a deadline."""
import sys
import unittest

import rospy
import rostest
from ros_test_support import RosTestSupport
from tf2_msgs.msg import TFMessage


class ReadmeCommands(RosTestSupport, unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("readme_commands_test")


    def test_rostopic_echo_tf(self):
        frames = set()
        subscriber = rospy.Subscriber(
            "/tf", TFMessage, lambda message: frames.update(t.child_frame_id for t in message.transforms))
        self.wait_for(lambda: "finger_interface" in frames, 30.0, "the demo's TF (finger_interface)")
        subscriber.unregister()
        output = self.run_command(["rostopic", "echo", "-n", "1", "/tf"])
        self.assertIn("transforms:", output)
        self.assertIn("child_frame_id:", output)
        self.assertIn('frame_id: "world"', output)
        print("rostopic echo -n 1 /tf: %d lines" % len(output.splitlines()))

    def test_rosservice_call_reset_scene(self):
        rospy.wait_for_service("/reset_scene", timeout=30)
        output = self.run_command(["rosservice", "call", "/reset_scene"])
        self.assertIn("success: True", output)
        self.assertIn("scene reset", output)
        print("rosservice call /reset_scene: %s" % " ".join(output.split()))


if __name__ == "__main__":
    rostest.rosrun("god_finger", "readme_commands", ReadmeCommands, sys.argv)
