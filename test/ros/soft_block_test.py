#!/usr/bin/python3
"""rostest: the soft block as a user presses it (demo.launch scene:=soft_block
device:=interactive). The block is on /markers as a triangle list in namespace `bodies` (its
surface, world frame); untouched, its top is flat near z = 0.1 m. The user drags the handle's
finger from its start (0.12 m up) to 1.5 cm past the top over 2 s: the hand feels the block
(feedback above 2 N), the surface under the finger sinks (its lowest point within 1 cm of the
axis goes more than 1 mm below where it rested) and its vertices there turn red (the marker's
per-vertex colours: red over green), and the finger's god-object rests on the dimple (within
1 mm of the surface's lowest point there, its radius above it). Waits on conditions with
deadlines."""
import math
import sys
import unittest

import rospy
import rostest
from geometry_msgs.msg import PointStamped, WrenchStamped
from god_finger.msg import DeviceState
from ros_test_support import RosTestSupport, drag_marker
from visualization_msgs.msg import InteractiveMarkerFeedback, Marker, MarkerArray

PROXY_RADIUS = 0.003  # m, the physics' default god-object


class SoftBlock(RosTestSupport, unittest.TestCase):
    def setUp(self):
        rospy.init_node("soft_block_test")
        self.surface = None  # the soft block's triangle list, the newest
        self.state = None
        self.proxy = None
        self.force = 0.0
        rospy.Subscriber("/markers", MarkerArray, self.on_markers, queue_size=5)
        rospy.Subscriber("/finger/device/state", DeviceState, self.on_state, queue_size=10)
        rospy.Subscriber("/finger/proxy", PointStamped, self.on_proxy, queue_size=10)
        rospy.Subscriber("/finger/feedback", WrenchStamped, self.on_feedback, queue_size=10)

    def on_markers(self, array):
        for marker in array.markers:
            if marker.ns == "bodies" and marker.type == Marker.TRIANGLE_LIST:
                self.surface = marker

    def on_state(self, message):
        self.state = message.position

    def on_proxy(self, message):
        self.proxy = message.point

    def on_feedback(self, message):
        f = message.wrench.force
        self.force = math.sqrt(f.x * f.x + f.y * f.y + f.z * f.z)

    def under_finger(self):
        """The surface's lowest point within 1 cm of the vertical axis (m), and the reddest of its
        vertices there (red minus green of the marker's colour)."""
        lowest, reddest = None, -1.0
        for point, colour in zip(self.surface.points, self.surface.colors):
            if math.hypot(point.x, point.y) < 0.01 and point.z > 0.05:
                lowest = point.z if lowest is None else min(lowest, point.z)
                reddest = max(reddest, colour.r - colour.g)
        return lowest, reddest

    def test_a_press_makes_a_dimple_the_user_sees_and_feels(self):
        self.wait_for(lambda: self.surface is not None, 30, "the soft block's surface on /markers")
        self.assertEqual(self.surface.header.frame_id, "world")
        self.assertEqual(len(self.surface.points) % 3, 0)
        self.assertEqual(len(self.surface.colors), len(self.surface.points))
        rest, red_at_rest = self.under_finger()
        self.assertAlmostEqual(rest, 0.1, delta=0.002, msg="the untouched top")
        drag = rospy.Publisher("/finger/device_marker/feedback", InteractiveMarkerFeedback, queue_size=10)
        self.wait_for(lambda: self.state is not None and drag.get_num_connections() > 0, 30,
                      "the handle's device state and its marker server")
        drag_marker(drag, self.state, 0.0, 0.0, 0.085, 2.0)
        self.wait_for(lambda: self.force > 2.0, 15, lambda: "the hand to feel the block (%.2f N)" % self.force)
        self.wait_for(lambda: self.under_finger()[0] < rest - 1e-3, 15,
                      lambda: "the dimple (the surface at %.4f m, at rest %.4f m)" % (self.under_finger()[0], rest))
        self.wait_for(lambda: self.proxy is not None and abs(self.proxy.z - PROXY_RADIUS - self.under_finger()[0]) < 1e-3,
                      15, lambda: "the god-object on the dimple (at %.4f m, the surface %.4f m)" %
                      (self.proxy.z, self.under_finger()[0]))
        lowest, reddest = self.under_finger()
        print("soft block: the top sank %.2f mm under %.2f N, the god-object %.2f mm above the dimple's bottom; "
              "red over green %.2f (at rest %.2f)" % (1e3 * (rest - lowest), self.force,
                                                      1e3 * (self.proxy.z - PROXY_RADIUS - lowest), reddest, red_at_rest))
        self.assertGreater(reddest, red_at_rest + 0.1, "the dimple is drawn redder")


if __name__ == "__main__":
    rostest.rosrun("god_finger", "soft_block", SoftBlock, sys.argv)
