#!/usr/bin/python3
"""rostest: launch/roll_finger.launch, servo topology (roll_finger.test) and processes
(roll_finger_processes.test: the orientation over DeviceState and the pose topic). The fake device's script
(config/scripts/roll_finger.yaml) presses the box's top with the finger pulp down, then rolls it
40 degrees about its own axis (x) from 0.8 s to 1.8 s of script time. In ROS, as offline: the
finger's contact area on the cube moves across the finger (y) by fingertip_radius x 40 degrees
(8 mm x 0.698 rad = 5.6 mm), the finger's pose (finger/pose) turns 40 degrees, and its feedback
wrench carries the rotational coupling's torque about x while it rolls. With ~max_torque > 0 (the
.test files give the fake profile torque_axes x and that max_torque), the device is given that
torque, saturated: DeviceState.applied_torque about x peaks at max_torque, none about y or z.
Waits on conditions with deadlines, never sleeps to synchronise."""
import math
import sys
import unittest

import rospy
import rostest
from geometry_msgs.msg import PoseStamped, WrenchStamped
from god_finger.msg import ContactAreaArray, DeviceState
from ros_test_support import RosTestSupport

TRAVEL = 0.008 * math.radians(40.0)  # m: fingertip_radius x the roll


class RollFinger(RosTestSupport, unittest.TestCase):
    def setUp(self):
        rospy.init_node("roll_finger_test")
        self.first = None  # the area's first centre on the cube (m, world), after touch-down
        self.last = None
        self.peak_torque = 0.0  # N m, |torque about x| on the hand
        self.turned = 0.0  # rad: the finger's pose from pulp down
        rospy.Subscriber("/contact_areas", ContactAreaArray, self.on_areas, queue_size=100)
        rospy.Subscriber("/finger/feedback", WrenchStamped, self.on_feedback, queue_size=100)
        rospy.Subscriber("/finger/pose", PoseStamped, self.on_pose, queue_size=100)
        # The servo waits for a subscriber here before it starts (wait_for_subscribers).
        rospy.Subscriber("/finger/device/state", DeviceState, self.on_state, queue_size=1000)
        self.device_torque = 0.0  # N m: the largest |applied torque about x| given to the device
        self.off_axes_torque = 0.0  # N m: the largest |applied torque about y or z|
        self.max_torque = rospy.get_param("~max_torque", 0.0)

    def on_state(self, message):
        t = message.applied_torque
        self.device_torque = max(self.device_torque, abs(t.x))
        self.off_axes_torque = max(self.off_axes_torque, abs(t.y), abs(t.z))

    def on_areas(self, message):
        for area in message.areas:
            if area.object == "cube" and area.radius > 0.0:
                point = (area.point.x, area.point.y, area.point.z)
                # After touch-down, before the roll the area stays put: the first one seen with
                # the finger pressing (radius > 0) is the roll's start.
                self.first = self.first or point
                self.last = point

    def on_feedback(self, message):
        self.peak_torque = max(self.peak_torque, abs(message.wrench.torque.x))

    def on_pose(self, message):
        q = message.pose.orientation
        # The angle from pulp down (180 degrees about x: w=0, x=1): 2 acos(|<q, q0>|).
        self.turned = 2.0 * math.acos(min(1.0, abs(q.x)))

    def travel(self):
        if self.first is None or self.last is None:
            return 0.0
        return math.hypot(self.last[0] - self.first[0], self.last[1] - self.first[1])

    def test_the_area_moves_and_the_torque_is_published(self):
        self.wait_for(lambda: self.turned > math.radians(39.5), 60, "the finger's pose rolled 40 degrees")
        self.wait_for(lambda: abs(self.travel() - TRAVEL) < 3e-4, 10, "the area moved by R_f x 40 degrees")
        print("roll_finger: area moved %.5f m (R_f theta %.5f m), finger turned %.4f rad, peak torque %.3g N m" %
              (self.travel(), TRAVEL, self.turned, self.peak_torque))
        self.assertLess(abs(self.last[0] - self.first[0]), 1e-4)  # across the finger, not along it
        self.assertGreater(self.peak_torque, 1e-5)
        if self.max_torque > 0.0:
            self.wait_for(lambda: self.device_torque >= self.max_torque * (1 - 1e-9), 10,
                          "the device given max_torque about x")
            print("roll_finger: device torque peak %.6g N m (max_torque %.6g)" % (self.device_torque, self.max_torque))
            self.assertLessEqual(self.device_torque, self.max_torque * (1 + 1e-9))
            self.assertEqual(self.off_axes_torque, 0.0)


if __name__ == "__main__":
    rostest.rosrun("god_finger", "roll_finger", RollFinger, sys.argv)
