#!/usr/bin/python3
"""rostest: /stop_force (std_srvs/SetBool), called as a user calls it (`rosservice call
/stop_force true`), while the hand presses the ball: the force applied to the device
(device/state applied_force, and device/force, the topic a user echoes) goes to zero and stays
exactly zero for a second of ticks while the coupling still asks for the press (feedback); after
`false` it ramps back in over the device's soft start (0.5 s for the fake device), never at once. Waits on conditions with
deadlines, never sleeps to synchronise."""
import math
import sys
import unittest

import rospy
import rostest
from ros_test_support import RosTestSupport
from geometry_msgs.msg import Vector3Stamped, WrenchStamped
from god_finger.msg import DeviceState

PRESSING = 0.5  # N: the press on the ball is well above it
SOFT_START = 0.5  # s: config/devices/fake.yaml


def norm(v):
    return math.sqrt(v.x * v.x + v.y * v.y + v.z * v.z)


class StopForce(RosTestSupport, unittest.TestCase):
    def setUp(self):
        rospy.init_node("stop_force_test")
        self.applied = []  # (stamp s, |applied_force| N) of every device state
        self.given = []  # |device/force| N: the force the device is given
        self.asked = []  # |feedback force| N: what the coupling asks of the hand
        rospy.Subscriber("/finger/device/state", DeviceState,
                         lambda m: self.applied.append((m.header.stamp.to_sec(), norm(m.applied_force))),
                         queue_size=5000)
        rospy.Subscriber("/finger/device/force", Vector3Stamped,
                         lambda m: self.given.append(norm(m.vector)), queue_size=5000)
        rospy.Subscriber("/finger/feedback", WrenchStamped,
                         lambda m: self.asked.append(norm(m.wrench.force)), queue_size=5000)

    def pressing(self):
        return len(self.applied) > 200 and all(f > PRESSING for _, f in self.applied[-200:])

    def test_stop_force_zeroes_the_force_and_resume_ramps_it_in(self):
        self.wait_for(self.pressing, 40.0, "the hand to press the ball (%.1f N for 200 ticks)" % PRESSING)
        pressed = self.applied[-1][1]

        before = len(self.applied)
        answer = self.run_command(["rosservice", "call", "/stop_force", "true"])
        self.assertIn("success: True", answer)
        self.assertIn("force stopped", answer)
        self.wait_for(lambda: any(f == 0.0 for _, f in self.applied[before:]), 5.0, "the force to stop")
        stopped = next(i for i in range(before, len(self.applied)) if self.applied[i][1] == 0.0)
        self.wait_for(lambda: len(self.applied) >= stopped + 1000, 10.0, "a second of ticks after the stop")
        held = self.applied[stopped:stopped + 1000]
        self.assertEqual([f for _, f in held if f != 0.0], [], "force applied while stopped")
        asked = self.asked[-500:]
        self.assertGreater(min(asked), PRESSING, "the coupling still asks for the press while stopped")
        given = self.given[-500:]
        self.assertEqual(len(given), 500)
        self.assertEqual([f for f in given if f != 0.0], [], "device/force shows a force while stopped")

        resume_from = len(self.applied)
        answer = self.run_command(["rosservice", "call", "/stop_force", "false"])
        self.assertIn("success: True", answer)
        self.assertIn("force resuming (soft start)", answer)
        self.wait_for(lambda: any(f > 0.9 * pressed for _, f in self.applied[resume_from:]), 5.0,
                      "the force back to 90 %% of the press (%.2f N)" % pressed)
        after = self.applied[resume_from:]
        first = next(i for i, (_, f) in enumerate(after) if f > 0.0)
        full = next(i for i, (_, f) in enumerate(after) if f > 0.9 * pressed)
        ramp = after[full][0] - after[first][0]
        print("stop_force: pressing %.2f N; %d ticks at exactly 0 N while the coupling asked %.2f-%.2f N; "
              "resumed: first %.4f N, 90 %% after %.3f s" % (pressed, len(held), min(asked), max(asked),
                                                             after[first][1], ramp))
        self.assertLess(after[first][1], 0.05 * pressed, "the force came back at once")
        # Linear over the soft start from the press the coupling asks (more than before the stop: the
        # handle sank meanwhile), 90 % of the earlier press takes about two thirds of it; at once: 0 s.
        self.assertGreater(ramp, 0.5 * SOFT_START, "the force came back faster than the soft start")
        self.assertLess(ramp, 1.5 * SOFT_START)


if __name__ == "__main__":
    rostest.rosrun("god_finger", "stop_force", StopForce, sys.argv)
