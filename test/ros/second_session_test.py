#!/usr/bin/python3
"""rostest: one session a master. With the demo running, a second `roslaunch god_finger ...`
on the same master (in each topology, and a scenario launch) exits non-zero with one line that
names the running session and how to run a second one, before it starts a node: the first
session's servo keeps its process and the finger's device state keeps coming."""
import os
import subprocess
import sys
import unittest

import rosgraph
import rospy
import rostest
from god_finger.msg import DeviceState
from ros_test_support import RosTestSupport

SECOND_LAUNCHES = (
    ["demo.launch"],
    ["demo.launch", "topology:=processes"],
    ["demo.launch", "topology:=nodelets", "device:=interactive"],
    ["pinch_cylinder.launch"],
)


class SecondSession(unittest.TestCase, RosTestSupport):
    def setUp(self):
        rospy.init_node("second_session_test")
        self.states = 0
        rospy.Subscriber("/finger/device/state", DeviceState, self.on_state, queue_size=100)

    def on_state(self, _):
        self.states += 1

    def servo_uri(self):
        try:
            return rosgraph.Master("/second_session_test").lookupNode("/servo")
        except rosgraph.MasterError:
            return None

    def test_a_second_launch_is_refused_and_the_first_runs_on(self):
        self.wait_for(lambda: self.servo_uri() is not None and self.states > 100, 60.0,
                      "the first session's servo and its device states")
        first_servo = self.servo_uri()
        for arguments in SECOND_LAUNCHES:
            command = ["roslaunch", "god_finger"] + arguments
            done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=60,
                                  universal_newlines=True, env=dict(os.environ))
            print("%s: exit %d" % (" ".join(command), done.returncode))
            self.assertNotEqual(done.returncode, 0, "%s was not refused:\n%s" % (" ".join(command), done.stdout))
            refusal = [line for line in done.stdout.splitlines() if "a session already runs on the master" in line]
            self.assertEqual(len(refusal), 1, "%s: no one-line refusal in:\n%s" % (" ".join(command), done.stdout))
            self.assertIn("node /god_finger_manager", refusal[0])
            self.assertIn("roslaunch -p", refusal[0], "the refusal says how to run a second session")
            self.assertNotIn("process[", done.stdout, "%s started a node before it was refused" % " ".join(command))
        # The first session is untouched: the same servo process, and its states still come.
        self.assertEqual(self.servo_uri(), first_servo)
        before = self.states
        self.wait_for(lambda: self.states > before + 100, 10.0, "device states after the refusals")


if __name__ == "__main__":
    rostest.rosrun("god_finger", "second_session", SecondSession, sys.argv)
