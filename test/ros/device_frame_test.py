#!/usr/bin/python3
"""rostest: in the default (servo) topology the device's frame is on /tf_static, world ->
finger_device, at the workspace mapping's offset, so that rviz shows the interactive handle
(it showed none, and its display turned to a warning, before)."""
import sys
import time
import unittest

import rospy
import rostest
from tf2_msgs.msg import TFMessage


class DeviceFrame(unittest.TestCase):
    def test_world_to_device_frame_is_static(self):
        rospy.init_node("device_frame_test")
        found = {}

        def on_static(message):
            for transform in message.transforms:
                found[transform.child_frame_id] = transform

        rospy.Subscriber("/tf_static", TFMessage, on_static, queue_size=10)
        deadline = time.time() + 40.0
        while "finger_device" not in found and time.time() < deadline and not rospy.is_shutdown():
            time.sleep(0.05)
        self.assertIn("finger_device", found, "no world -> finger_device on /tf_static within 40 s")
        transform = found["finger_device"]
        self.assertEqual(transform.header.frame_id, "world")
        # The launch's workspace offset (device_frame.test), no rotation (the fake profile's).
        offset = rospy.get_param("/finger/workspace_offset")
        self.assertEqual(offset, [0.1, -0.02, 0.05])
        t = transform.transform.translation
        self.assertAlmostEqual(t.x, offset[0], places=9)
        self.assertAlmostEqual(t.y, offset[1], places=9)
        self.assertAlmostEqual(t.z, offset[2], places=9)
        self.assertAlmostEqual(transform.transform.rotation.w, 1.0, places=9)


if __name__ == "__main__":
    rostest.rosrun("god_finger", "device_frame", DeviceFrame, sys.argv)
