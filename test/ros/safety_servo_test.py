#!/usr/bin/python3
"""rostest: non-finite device readings on the servo topology (safety_servo.test: 0.5 s of the
fake device's readings non-finite, every button pressed). As on the topic topologies, such a
reading is rejected whole and counted once (rejected_readings: one per tick of the window), is
never passed on (device/state, pose, feedback and proxy stay finite: device/state carries the
last good reading), and its buttons press nothing (the contact model stays the launch's)."""
import math
import sys
import time
import unittest

import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import PointStamped, PoseStamped, WrenchStamped
from god_finger.msg import DeviceState

STATUS = "/servo: servo loop"  # the servo nodelet's own name, then what it reports on


def finite(*vectors):
    return all(math.isfinite(v.x) and math.isfinite(v.y) and math.isfinite(v.z) for v in vectors)


class SafetyServo(unittest.TestCase):
    def setUp(self):
        rospy.init_node("safety_servo_test")
        self.states = 0
        self.non_finite = 0
        self.pressed = 0
        self.rejected = []  # rejected_readings of each diagnostics message
        self.model = None
        rospy.Subscriber("/finger/device/state", DeviceState, self.on_state, queue_size=5000)
        rospy.Subscriber("/finger/pose", PoseStamped, lambda m: self.count(finite(m.pose.position)), queue_size=5000)
        rospy.Subscriber("/finger/feedback", WrenchStamped, lambda m: self.count(finite(m.wrench.force)),
                         queue_size=5000)
        rospy.Subscriber("/finger/proxy", PointStamped, lambda m: self.count(finite(m.point)), queue_size=5000)
        rospy.Subscriber("/diagnostics", DiagnosticArray, self.on_diagnostics, queue_size=10)

    def count(self, is_finite):
        self.non_finite += 0 if is_finite else 1

    def on_state(self, message):
        self.states += 1
        self.count(finite(message.position, message.velocity, message.applied_force))
        self.pressed += 1 if message.buttons else 0

    def on_diagnostics(self, message):
        for status in message.status:
            if not status.name.endswith(STATUS):
                continue
            values = {pair.key: pair.value for pair in status.values}
            self.model = values.get("contact_model")
            self.rejected.append(int(values["rejected_readings"]))

    def wait_for(self, condition, seconds, what):
        deadline = time.time() + seconds
        while not condition() and time.time() < deadline:
            time.sleep(0.05)
        self.assertTrue(condition(), "waited %.0f s for %s" % (seconds, what))

    def test_non_finite_readings_are_counted_once_and_never_passed_on(self):
        self.wait_for(lambda: self.rejected and self.rejected[-1] > 0, 40.0, "the faulty readings")
        # The window is over when the count stops growing (two diagnostics in a row, 1 Hz).
        self.wait_for(lambda: len(self.rejected) >= 2 and self.rejected[-1] == self.rejected[-2] > 0, 10.0,
                      "the faulty readings to end")
        rejected = self.rejected[-1]
        print("servo topology: %d readings rejected (500 ticks non-finite), %d device states, %d non-finite "
              "passed on, %d with a button pressed, model %s" % (rejected, self.states, self.non_finite,
                                                                 self.pressed, self.model))
        self.assertGreaterEqual(rejected, 499)  # one count per tick of [1.0, 1.5) s, at 1 kHz
        self.assertLessEqual(rejected, 501)
        self.assertGreater(self.states, 1000)
        self.assertEqual(self.non_finite, 0)
        self.assertEqual(self.pressed, 0)
        self.assertEqual(self.model, "god_finger")  # button 0 pressed for 0.5 s would have cycled it


if __name__ == "__main__":
    rostest.rosrun("god_finger", "safety_servo", SafetyServo, sys.argv)
