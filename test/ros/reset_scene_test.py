#!/usr/bin/python3
"""rostest: reset_scene means the same in every topology (src/ros/world_services.h): the scene
back to its initial state, each proxy restarting where its hand is now. The interactive
device's hand is dragged 8 cm from where it started, in free space; after the reset no proxy
message is more than 5 mm from the hand: the proxy did not jump back to where it started,
which would throw the hand toward it at the device's force limit."""
import math
import sys
import threading
import unittest

import rospy
import rostest
from geometry_msgs.msg import PointStamped, PoseStamped
from god_finger.msg import DeviceState
from ros_test_support import RosTestSupport, drag_marker
from std_srvs.srv import Trigger
from visualization_msgs.msg import InteractiveMarkerFeedback


def distance(a, b):
    return math.sqrt((a.x - b.x) ** 2 + (a.y - b.y) ** 2 + (a.z - b.z) ** 2)


class ResetScene(RosTestSupport, unittest.TestCase):
    def setUp(self):
        rospy.init_node("reset_scene_test")
        self.lock = threading.Lock()
        self.state = None  # device frame
        self.hand = None  # world: the interface's pose
        self.proxy = None  # world
        self.after_reset = None  # the largest proxy-to-hand distance since the reset was called (m)
        self.proxies_after_reset = 0
        rospy.Subscriber("/finger/device/state", DeviceState, self.on_state, queue_size=10)
        rospy.Subscriber("/finger/pose", PoseStamped, self.on_pose, queue_size=10)
        rospy.Subscriber("/finger/proxy", PointStamped, self.on_proxy, queue_size=100)
        self.drag = rospy.Publisher("/finger/device_marker/feedback", InteractiveMarkerFeedback, queue_size=10)

    def on_state(self, message):
        self.state = message.position

    def on_pose(self, message):
        with self.lock:
            self.hand = message.pose.position

    def on_proxy(self, message):
        with self.lock:
            self.proxy = message.point
            if self.after_reset is not None and self.hand is not None:
                self.after_reset = max(self.after_reset, distance(self.proxy, self.hand))
                self.proxies_after_reset += 1

    def test_the_proxy_restarts_at_the_hand(self):
        self.wait_for(lambda: self.state is not None and self.hand is not None and self.proxy is not None, 30.0,
                      "device states, poses and proxies")
        self.wait_for(lambda: self.drag.get_num_connections() > 0, 10.0,
                      "the marker server to subscribe to the marker's feedback")
        with self.lock:
            start = self.proxy
        drag_marker(self.drag, self.state, 0.08, 0.02, 0.12, 1.0)  # beside the ball, free space
        self.wait_for(lambda: distance(self.proxy, self.hand) < 0.002 and distance(self.proxy, start) > 0.05, 10.0,
                      "the proxy to follow the hand 5 cm or more from where it started, in free space")
        rospy.wait_for_service("reset_scene", timeout=10)
        with self.lock:
            self.after_reset = 0.0
        response = rospy.ServiceProxy("reset_scene", Trigger)()
        self.assertTrue(response.success, response.message)
        self.assertEqual(response.message, "scene reset")
        self.wait_for(lambda: self.proxies_after_reset >= 200, 20.0, "200 proxy messages after the reset")
        print("reset_scene: proxy at most %.2f mm from the hand over %d messages after the reset"
              % (1e3 * self.after_reset, self.proxies_after_reset))
        self.assertLess(self.after_reset, 0.005)


if __name__ == "__main__":
    rostest.rosrun("god_finger", "reset_scene", ResetScene, sys.argv)
