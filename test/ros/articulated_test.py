#!/usr/bin/python3
"""rostest: articulated objects as a user runs them (launch/door.launch, launch/drawer.launch).
The scene's joint is on /joint_states (sensor_msgs/JointState) and its links on TF.
- door, device:=interactive: the user drags the rviz handle's finger from in front of the door
  through its face, 20 cm along +y; the door turns open on its hinge (past 0.5 rad) and the hand
  feels the push.
- drawer (the fake device's script, on simulated time): the finger presses the drawer's top and
  pulls it 12 cm out by friction; the runners' joint ends within 5 mm of 0.12 m.
The case comes from the test's parameter `case` (door or drawer)."""
import math
import sys
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import WrenchStamped
from god_finger.msg import DeviceState
from ros_test_support import drag_marker
from sensor_msgs.msg import JointState
from tf2_msgs.msg import TFMessage
from visualization_msgs.msg import InteractiveMarkerFeedback


class Articulated(unittest.TestCase):
    def setUp(self):
        rospy.init_node("articulated_test")
        self.joints = None
        self.state = None
        self.force = 0.0
        rospy.Subscriber("/joint_states", JointState, self.on_joints, queue_size=10)
        rospy.Subscriber("/finger/device/state", DeviceState, self.on_state, queue_size=10)
        rospy.Subscriber("/finger/feedback", WrenchStamped, self.on_feedback, queue_size=10)
        self.frames = set()  # child frames seen on /tf
        rospy.Subscriber("/tf", TFMessage, self.on_tf, queue_size=100)

    def on_tf(self, message):
        for transform in message.transforms:
            self.frames.add(transform.child_frame_id)

    def on_joints(self, message):
        self.joints = dict(zip(message.name, message.position))

    def on_state(self, message):
        self.state = message.position

    def on_feedback(self, message):
        f = message.wrench.force
        self.force = max(self.force, math.sqrt(f.x * f.x + f.y * f.y + f.z * f.z))

    def wait_for(self, condition, seconds, what):
        """Polls `condition` until it holds or `seconds` (wall clock) pass; fails naming `what`."""
        deadline = time.time() + seconds
        while not condition() and time.time() < deadline:
            time.sleep(0.05)
        self.assertTrue(condition(), "waited %.0f s for %s" % (seconds, what() if callable(what) else what))

    def joint(self, name):
        return None if self.joints is None else self.joints.get(name)

    def test_articulated(self):
        case = rospy.get_param("~case")
        link = {"door": "door", "drawer": "drawer"}[case]
        name = {"door": "hinge", "drawer": "runners"}[case]
        self.wait_for(lambda: self.joint(name) is not None, 30.0, "/joint_states to carry joint '%s'" % name)
        self.wait_for(lambda: link in self.frames, 10.0, "the link '%s' on /tf" % link)
        if case == "door":
            self.assertAlmostEqual(self.joint(name), 0.0, delta=0.01, msg="the door starts closed")
            drag = rospy.Publisher("/finger/device_marker/feedback", InteractiveMarkerFeedback, queue_size=10)
            self.wait_for(lambda: self.state is not None and drag.get_num_connections() > 0, 30.0,
                          "the handle's device state and its marker server")
            # From in front of the door (the handle's start, world (0.2, -0.08, 0.2)) through its
            # face, 20 cm along +y: the finger pushes the door open.
            drag_marker(drag, self.state, 0.0, 0.2, 0.0, 2.0)
            self.wait_for(lambda: self.joint(name) > 0.5, 15.0,
                          lambda: "the door to open past 0.5 rad (at %.3f rad)" % self.joint(name))
            print("articulated: the door opened to %.3f rad, the hand felt up to %.2f N" % (self.joint(name), self.force))
            self.assertGreater(self.force, 0.05, "the hand feels the door")
        else:
            self.wait_for(lambda: abs(self.joint(name) - 0.12) < 0.005, 40.0,
                          lambda: "the drawer to be pulled 0.12 m out (at %.4f m)" % self.joint(name))
            print("articulated: the drawer pulled out %.4f m" % self.joint(name))


if __name__ == "__main__":
    rostest.rosrun("god_finger", "articulated", Articulated, sys.argv)
