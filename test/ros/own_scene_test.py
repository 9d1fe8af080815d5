#!/usr/bin/python3
"""rostest: demo.launch scene_file:=test/data/own_scene/own_scene.urdf runs the user's scene: its
three bodies (a primitive table, a package:// mesh, a mesh by relative path) are on TF, where
the URDF puts them, and not the default scene's ball. Waits on the condition with a deadline."""
import sys
import unittest

import rospy
import rostest
from ros_test_support import RosTestSupport
from tf2_msgs.msg import TFMessage


class OwnScene(RosTestSupport, unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("own_scene_test")

    def test_bodies_of_the_own_scene_are_on_tf(self):
        positions = {}

        def on_tf(message):
            for transform in message.transforms:
                t = transform.transform.translation
                positions[transform.child_frame_id] = (t.x, t.y, t.z)

        subscriber = rospy.Subscriber("/tf", TFMessage, on_tf)
        expected = {"own_table": (0.0, 0.0, -0.02), "own_widget": (0.25, 0.0, 0.02), "own_pebble": (-0.25, 0.0, 0.025)}
        self.wait_for(lambda: all(name in positions for name in expected), 30.0, "the own scene's bodies on TF")
        subscriber.unregister()
        for name, (x, y, z) in expected.items():
            # resting on the table: within 2 mm of where the URDF puts them
            for axis, (got, want) in enumerate(zip(positions[name], (x, y, z))):
                self.assertAlmostEqual(got, want, delta=0.002, msg="%s axis %d: %s" % (name, axis, positions[name]))
        self.assertNotIn("ball", positions, "the default scene's ball: scene_file was not used")


if __name__ == "__main__":
    rostest.rosrun("god_finger", "own_scene", OwnScene, sys.argv)
