#!/usr/bin/python3
"""rostest: a hand tracker broadcasts three fingertip frames on TF (thumb_tip, index_tip,
middle_tip in world; the pose_source's `frames`), each 5 mm into the table: every finger
presses (its feedback above 1 N) and its interface pose (NAME/pose, the mapped target, world)
is the frame's position within 1 mm. The frames move 2 cm along y: every finger follows.
Then middle_tip stops being broadcast: TF keeps its last transform, whose stamp ages past
pose_timeout (1 s here, see
pose_source_tf.test), so the servo lets the middle finger go (feedback under 0.01 N, a WARN
`finger hand/middle` on /diagnostics) while the thumb and index go on pressing where their
frames are. Broadcast at 100 Hz; the test waits on conditions with deadlines, never sleeps to
synchronise."""
import math
import sys
import unittest

import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticStatus
from geometry_msgs.msg import PoseStamped, TransformStamped, WrenchStamped
from ros_test_support import RosTestSupport
from tf2_msgs.msg import TFMessage

FINGERS = ["thumb", "index", "middle"]
START = {"thumb": (0.15, 0.1, -0.005), "index": (0.2, 0.1, -0.005), "middle": (0.25, 0.1, -0.005)}  # m, world
MOVE = (0.0, 0.02, 0.0)  # m: where the hand moves, every finger still 5 mm into the table
PRESSING = 1.0  # N: 5 mm at the fake profile's 400 N/m is 2 N
FOLLOWS = 1e-3  # m: an interface pose within this of its frame


def norm(v):
    return math.sqrt(v.x * v.x + v.y * v.y + v.z * v.z)


class PoseSourceFromTf(RosTestSupport, unittest.TestCase):
    def setUp(self):
        rospy.init_node("pose_source_tf_test")
        self.where = dict(START)  # finger -> its frame's position (m, world)
        self.broadcast = set(FINGERS)  # the frames the tracker still broadcasts
        self.force = {}  # finger -> |feedback force| N, the newest
        self.pose = {}  # finger -> its interface position (x, y, z), the newest
        self.status = self.watch_finger_statuses(FINGERS)  # finger -> its newest diagnostic status
        for name in FINGERS:
            rospy.Subscriber("/hand/%s/feedback" % name, WrenchStamped,
                             lambda m, name=name: self.force.__setitem__(name, norm(m.wrench.force)), queue_size=1)
            rospy.Subscriber("/hand/%s/pose" % name, PoseStamped,
                             lambda m, name=name: self.pose.__setitem__(
                                 name, (m.pose.position.x, m.pose.position.y, m.pose.position.z)), queue_size=1)
        self.broadcaster = rospy.Publisher("/tf", TFMessage, queue_size=100)  # as tf2_ros' broadcaster does
        self.timer = rospy.Timer(rospy.Duration(0.01), self.track)

    def track(self, _event):
        transforms = []
        for name in FINGERS:
            if name not in self.broadcast:
                continue
            transform = TransformStamped()
            transform.header.stamp = rospy.Time.now()
            transform.header.frame_id = "world"
            transform.child_frame_id = name + "_tip"
            (transform.transform.translation.x, transform.transform.translation.y,
             transform.transform.translation.z) = self.where[name]
            transform.transform.rotation.w = 1.0
            transforms.append(transform)
        self.broadcaster.publish(TFMessage(transforms=transforms))

    def pressing(self, name):
        return self.force.get(name, 0.0) > PRESSING

    def error(self, name):
        """m: the finger's interface pose from its frame's position."""
        if name not in self.pose:
            return float("inf")
        return math.sqrt(sum((a - b) ** 2 for a, b in zip(self.pose[name], self.where[name])))

    def following(self, names):
        return all(self.pressing(name) and self.error(name) < FOLLOWS for name in names)

    def test_fingers_follow_their_frames_and_a_lost_frame_lets_go(self):
        self.wait_for(lambda: self.following(FINGERS), 30, "every finger pressing at its frame")
        for name in FINGERS:
            self.where[name] = tuple(a + b for a, b in zip(START[name], MOVE))
        self.wait_for(lambda: self.following(FINGERS), 10, "every finger following its frame 2 cm along y")
        print("following: " + ", ".join("%s %.2f N, %.2e m from its frame" % (n, self.force[n], self.error(n))
                                       for n in FINGERS))
        self.broadcast.discard("middle")  # the tracker loses the middle fingertip's frame
        self.wait_for(lambda: self.force.get("middle", 1.0) < 0.01, 10, "the middle finger letting go")
        self.wait_for(lambda: "middle" in self.status and self.status["middle"].level == DiagnosticStatus.WARN, 10,
                      "a diagnostic naming the lost finger")
        self.assertIn("let go", self.status["middle"].message)
        self.assertTrue(self.following(["thumb", "index"]),
                        "thumb and index: %s N, errors %.2e, %.2e m" % (self.force, self.error("thumb"),
                                                                       self.error("index")))
        # Their diagnostics (at the servo's diagnostic period) say tracked, not let go.
        self.wait_for(lambda: all(self.status.get(name, DiagnosticStatus()).level != DiagnosticStatus.WARN
                                  for name in ("thumb", "index")), 10, "thumb and index not reported let go")
        print("lost frame: %s: %s; thumb %.2f N, index %.2f N, middle %.4f N" %
              (self.status["middle"].name, self.status["middle"].message, self.force["thumb"], self.force["index"],
               self.force["middle"]))
        self.timer.shutdown()

    def tearDown(self):
        self.timer.shutdown()


if __name__ == "__main__":
    rostest.rosrun("god_finger", "pose_source_tf", PoseSourceFromTf, sys.argv)
