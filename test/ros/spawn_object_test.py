#!/usr/bin/python3
"""rostest: spawn_object and delete_object (src/ros/world_services.h) in the running world, as a
user calls them: a block of ours is spawned, fixed, under the interactive hand; TF shows it, rviz's
markers show one body more; the hand dragged down presses it (a contact area on 'block', force on
the device); deleted while pressed, the markers lose it, the contact areas stop naming it and the
device's force falls to zero (the finger lets go). Bad requests are refused naming the problem."""
import sys
import threading
import unittest

import rospy
import rostest
from geometry_msgs.msg import PointStamped, PoseStamped
from god_finger.msg import ContactAreaArray, DeviceState
from god_finger.srv import DeleteObject, SpawnObject, SpawnObjectRequest
from tf2_msgs.msg import TFMessage
from ros_test_support import RosTestSupport, drag_marker
from visualization_msgs.msg import InteractiveMarkerFeedback, MarkerArray


def norm(v):
    return (v.x ** 2 + v.y ** 2 + v.z ** 2) ** 0.5


class SpawnObject_(RosTestSupport, unittest.TestCase):
    def setUp(self):
        rospy.init_node("spawn_object_test")
        self.lock = threading.Lock()
        self.state = None  # device frame
        self.force = 0.0  # N, applied on the device
        self.hand = None  # world
        self.proxy = None
        self.body_markers = None  # markers in the 'bodies' namespace, the last array
        self.touched = set()  # bodies in the last contact-area message
        self.block_frame = None  # z (m) of the last TF world -> block
        rospy.Subscriber("/tf", TFMessage, self.on_tf, queue_size=100)
        rospy.Subscriber("/finger/device/state", DeviceState, self.on_state, queue_size=10)
        rospy.Subscriber("/finger/pose", PoseStamped, self.on_pose, queue_size=10)
        rospy.Subscriber("/finger/proxy", PointStamped, self.on_proxy, queue_size=10)
        rospy.Subscriber("/markers", MarkerArray, self.on_markers, queue_size=10)
        rospy.Subscriber("/contact_areas", ContactAreaArray, self.on_areas, queue_size=10)
        self.drag = rospy.Publisher("/finger/device_marker/feedback", InteractiveMarkerFeedback, queue_size=10)

    def on_state(self, message):
        with self.lock:
            self.state = message.position
            self.force = norm(message.applied_force)

    def on_pose(self, message):
        self.hand = message.pose.position

    def on_proxy(self, message):
        self.proxy = message.point

    def on_markers(self, message):
        with self.lock:
            self.body_markers = sum(1 for m in message.markers if m.ns == "bodies" and m.action == m.ADD)

    def on_areas(self, message):
        with self.lock:
            self.touched = set(area.object for area in message.areas)

    def on_tf(self, message):
        for transform in message.transforms:
            if transform.header.frame_id == "world" and transform.child_frame_id == "block":
                self.block_frame = transform.transform.translation.z

    def block_z(self):
        return self.block_frame

    def test_spawn_touch_delete(self):
        self.wait_for(lambda: None not in (self.state, self.hand, self.proxy, self.body_markers), 30.0,
                      "device states, poses, proxies and markers")
        self.wait_for(lambda: self.drag.get_num_connections() > 0, 10.0, "the marker server")
        before = self.body_markers
        rospy.wait_for_service("spawn_object", timeout=10)
        spawn = rospy.ServiceProxy("spawn_object", SpawnObject)
        delete = rospy.ServiceProxy("delete_object", DeleteObject)

        # Bad requests: refused, naming the problem, nothing added.
        bad = spawn(name="x", file="objects/block.urdf")
        self.assertFalse(bad.success)
        self.assertIn("absolute path", bad.message)
        bad = spawn(name="x", file="package://god_finger/urdf/objects/none.urdf")
        self.assertFalse(bad.success)
        self.assertIn("none.urdf", bad.message)
        bad = spawn(name="ball", file="package://god_finger/urdf/objects/block.urdf")  # the scene's ball
        self.assertFalse(bad.success)
        self.assertIn("'ball' already", bad.message)
        bad = spawn(name="a/b", file="package://god_finger/urdf/objects/block.urdf")  # not a TF-safe name
        self.assertFalse(bad.success)
        self.assertIn("letters, digits", bad.message)
        missing = delete(name="nothing")
        self.assertFalse(missing.success)
        self.assertIn("no body named 'nothing'", missing.message)

        # A 6 x 4 x 3 cm block, fixed, its top 6 mm under the resting proxy.
        hand = self.hand
        request = SpawnObjectRequest(name="block", file="package://god_finger/urdf/objects/block.urdf",
                                     fixed=SpawnObjectRequest.FIXED)
        request.pose.position.x = hand.x
        request.pose.position.y = hand.y
        request.pose.position.z = hand.z - 0.003 - 0.006 - 0.015
        answer = spawn(request)
        self.assertTrue(answer.success, answer.message)
        self.assertIn("added 1 body", answer.message)
        self.wait_for(lambda: self.block_z() is not None, 10.0, "TF of the spawned block")
        self.assertAlmostEqual(self.block_z(), request.pose.position.z, places=6)
        self.wait_for(lambda: self.body_markers == before + 1, 10.0, "rviz's markers to show one body more")
        twice = spawn(request)
        self.assertFalse(twice.success)
        self.assertIn("'block' already", twice.message)

        # Pressed: the hand 2 cm down, through the block's top.
        with self.lock:
            start = self.state
        drag_marker(self.drag, start, start.x, start.y, start.z - 0.02, 1.0)
        self.wait_for(lambda: "block" in self.touched and self.force > 1.0, 10.0,
                      "a contact area on the block and more than 1 N on the device")
        print("spawn_object: pressing the spawned block with %.2f N" % self.force)

        deleted = delete(name="block")
        self.assertTrue(deleted.success, deleted.message)
        self.assertEqual(deleted.message, "deleted 1 body(ies)")
        self.wait_for(lambda: self.body_markers == before and "block" not in self.touched, 10.0,
                      "the markers and contact areas without the block")
        self.wait_for(lambda: self.force < 0.05, 5.0, "the finger to let go (no force on the device)")
        print("spawn_object: deleted, the device's force %.3f N" % self.force)


if __name__ == "__main__":
    rostest.rosrun("god_finger", "spawn_object", SpawnObject_, sys.argv)
