#!/usr/bin/python3
"""rostest: a long idle run of a device publishes no subnormal number. An idle loop is where
values decay toward zero (a settling handle, a damped velocity, a fading force): left alone,
they walk into the subnormal range, where x86 arithmetic is many times slower and where the
fake handle once stuck at the smallest subnormal (1.5e-323 on TF). The demo runs on simulated
time (the same run every time) for ~seconds of simulated time, the device idle after its
first seconds; every float of every message on the session's topics is checked."""
import math
import sys
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import PointStamped, PoseStamped, Vector3Stamped, WrenchStamped
from god_finger.msg import ContactAreaArray, DeviceState
from rosgraph_msgs.msg import Clock
from tf2_msgs.msg import TFMessage
from visualization_msgs.msg import MarkerArray

SMALLEST_NORMAL = 2.2250738585072014e-308


def floats(message):
    """Every float in a ROS message, however nested."""
    if isinstance(message, float):
        yield message
    elif isinstance(message, (list, tuple)):
        for item in message:
            yield from floats(item)
    elif hasattr(message, "__slots__"):
        for slot in message.__slots__:
            yield from floats(getattr(message, slot))


class IdleSubnormals(unittest.TestCase):
    def setUp(self):
        rospy.init_node("idle_subnormals_test")
        self.interface = rospy.get_param("~interface", "finger")
        self.seconds = rospy.get_param("~seconds", 120.0)
        self.checked = {}
        self.subnormal = {}
        self.now = 0.0
        topics = [("/tf", TFMessage), ("/markers", MarkerArray), ("/contact_areas", ContactAreaArray)]
        for name in rospy.get_param("~interfaces", [self.interface]):
            topics += [("/%s/device/state" % name, DeviceState), ("/%s/device/force" % name, Vector3Stamped),
                       ("/%s/feedback" % name, WrenchStamped), ("/%s/pose" % name, PoseStamped),
                       ("/%s/proxy" % name, PointStamped)]
        for topic, kind in topics:
            self.checked[topic] = 0
            self.subnormal[topic] = []
            rospy.Subscriber(topic, kind, self.checker(topic), queue_size=1000)
        rospy.Subscriber("/clock", Clock, self.on_clock, queue_size=10)

    def checker(self, topic):
        def check(message):
            for value in floats(message):
                self.checked[topic] += 1
                if value != 0.0 and abs(value) < SMALLEST_NORMAL:
                    self.subnormal[topic].append(value)
        return check

    def on_clock(self, message):
        self.now = message.clock.to_sec()

    def test_no_subnormal_on_any_topic(self):
        deadline = time.time() + 240.0
        while self.now < self.seconds and time.time() < deadline:
            time.sleep(0.1)  # polls the simulated clock within the deadline
        self.assertGreaterEqual(self.now, self.seconds, "the simulated clock reached only %.1f s" % self.now)
        total = sum(self.checked.values())
        print("idle_subnormals: %.0f s simulated, %d floats checked on %d topics, %d subnormal"
              % (self.now, total, len(self.checked), sum(len(v) for v in self.subnormal.values())))
        for topic in sorted(self.checked):
            print("  %s: %d floats, %d subnormal" % (topic, self.checked[topic], len(self.subnormal[topic])))
        self.assertGreater(self.checked["/%s/device/state" % self.interface], 10000, "too few device states checked")
        for topic, values in self.subnormal.items():
            self.assertEqual(values, [], "%s published subnormal numbers: %s" % (topic, values[:5]))


if __name__ == "__main__":
    rostest.rosrun("god_finger", "idle_subnormals", IdleSubnormals, sys.argv)
