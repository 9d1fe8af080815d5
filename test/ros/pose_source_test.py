#!/usr/bin/python3
"""rostest: a hand tracker publishes three fingertips (thumb, index, middle) on /hand/poses,
each 5 mm into the table: every finger presses (its feedback, the coupling's reaction, above
1 N). Then the tracker drops the middle finger from its arrays: within its pose_timeout (1 s here, see
pose_source.test) plus the diagnostics' period the servo reports `finger hand/middle` as let go (WARN, on
/diagnostics), its feedback falls to zero, and the thumb and index go on pressing. The tracker
publishes at 100 Hz; the test waits on conditions with deadlines, never sleeps to synchronise."""
import math
import sys
import unittest

import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticStatus
from geometry_msgs.msg import Pose, PoseArray, WrenchStamped
from ros_test_support import RosTestSupport

FINGERS = ["thumb", "index", "middle"]
PRESSED = [(0.15, 0.1, -0.005), (0.2, 0.1, -0.005), (0.25, 0.1, -0.005)]  # m, world: 5 mm into the table
PRESSING = 1.0  # N: 5 mm at the fake profile's 400 N/m is 2 N


def norm(v):
    return math.sqrt(v.x * v.x + v.y * v.y + v.z * v.z)


class PoseSourceLetsGo(RosTestSupport, unittest.TestCase):
    def setUp(self):
        rospy.init_node("pose_source_test")
        self.seen = len(FINGERS)  # how many fingers the tracker sees
        self.force = {}  # finger -> |feedback force| N, the newest
        self.lost = self.watch_finger_statuses(FINGERS)  # finger -> its newest diagnostic status
        for name in FINGERS:
            rospy.Subscriber("/hand/%s/feedback" % name, WrenchStamped,
                             lambda m, name=name: self.force.__setitem__(name, norm(m.wrench.force)), queue_size=1)
        self.publisher = rospy.Publisher("/hand/poses", PoseArray, queue_size=10)
        self.timer = rospy.Timer(rospy.Duration(0.01), self.track)

    def track(self, _event):
        message = PoseArray()
        message.header.stamp = rospy.Time.now()
        message.header.frame_id = "world"
        for x, y, z in PRESSED[:self.seen]:
            pose = Pose()
            pose.position.x, pose.position.y, pose.position.z = x, y, z
            pose.orientation.w = 1.0
            message.poses.append(pose)
        self.publisher.publish(message)

    def pressing(self, name):
        return self.force.get(name, 0.0) > PRESSING

    def test_a_lost_finger_lets_go_with_a_diagnostic_the_others_go_on(self):
        self.wait_for(lambda: all(self.pressing(name) for name in FINGERS), 30, "every finger pressing the table")
        self.seen = 2  # the tracker loses the middle finger
        self.wait_for(lambda: self.force.get("middle", 1.0) < 0.01, 10, "the middle finger letting go")
        self.wait_for(lambda: "middle" in self.lost and self.lost["middle"].level == DiagnosticStatus.WARN, 10,
                      "a diagnostic naming the lost finger")
        self.assertIn("let go", self.lost["middle"].message)
        # Named for why: the array now has two poses for three fingers.
        self.assertIn("missing from the pose array", self.lost["middle"].message)
        self.assertTrue(self.lost["middle"].name.startswith("/servo: finger hand/"), self.lost["middle"].name)
        print("lost finger: %s: %s; thumb %.2f N, index %.2f N, middle %.4f N" %
              (self.lost["middle"].name, self.lost["middle"].message, self.force["thumb"], self.force["index"],
               self.force["middle"]))
        self.assertTrue(self.pressing("thumb") and self.pressing("index"), self.force)
        for name in ("thumb", "index"):  # before their first pose they were untracked; since, tracked
            self.assertNotEqual(self.lost.get(name, DiagnosticStatus()).level, DiagnosticStatus.WARN, name)
            self.assertEqual(self.lost.get(name, DiagnosticStatus()).message in ("", "tracked again"), True, name)
        self.seen = 3  # seen again: it presses again
        self.wait_for(lambda: self.pressing("middle"), 10, "the middle finger pressing again")
        self.timer.shutdown()


if __name__ == "__main__":
    rostest.rosrun("god_finger", "pose_source", PoseSourceLetsGo, sys.argv)
