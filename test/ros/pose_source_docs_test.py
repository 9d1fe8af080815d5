#!/usr/bin/python3
"""rostest: docs/devices.md's pose_source example, run as written. Its two `rostopic pub`
commands (come down beside the mug, then press) are read from the page and run as a user runs
them, the first stopped (SIGINT, as Ctrl-C) once every finger is there. Then every fingertip's
proxy must press the mug from outside: outside its 4 cm wall (measured from the mug's axis,
wherever the press moved it), below its 9 cm rim, with a force on the hand. Waits on
conditions with deadlines, never sleeps to synchronise."""
import math
import os
import re
import shlex
import signal
import subprocess
import sys
import unittest

import rospkg
import rospy
import rostest
from geometry_msgs.msg import PointStamped, WrenchStamped
from ros_test_support import RosTestSupport
from tf2_msgs.msg import TFMessage

PACKAGE = rospkg.RosPack().get_path("god_finger")
FINGERS = ["thumb", "index", "middle"]
MUG_RADIUS = 0.04  # m: urdf/scenes/table_mug.urdf's mug, outer wall
MUG_HEIGHT = 0.09  # m


def documented_commands():
    """The `rostopic pub ... /hand/poses` commands of docs/devices.md, in order, as argument lists."""
    with open(os.path.join(PACKAGE, "docs", "devices.md")) as f:
        text = f.read().replace("\\\n", " ")
    return [shlex.split(line.strip()) for line in text.splitlines() if re.match(r"\s*rostopic pub .*/hand/poses", line)]


def poses_of(command):
    """(x, y, z) of each pose in a command's message."""
    return [tuple(float(v) for v in m) for m in
            re.findall(r"x: (-?[\d.]+), y: (-?[\d.]+), z: (-?[\d.]+)", command[-1])]


class PoseSourceDocs(RosTestSupport, unittest.TestCase):
    def setUp(self):
        rospy.init_node("pose_source_docs_test")
        self.proxy = {}
        self.force = {}
        for name in FINGERS:
            rospy.Subscriber("/hand/%s/proxy" % name, PointStamped,
                             lambda m, name=name: self.proxy.__setitem__(name, (m.point.x, m.point.y, m.point.z)),
                             queue_size=1)
            rospy.Subscriber("/hand/%s/feedback" % name, WrenchStamped,
                             lambda m, name=name: self.force.__setitem__(
                                 name, math.sqrt(m.wrench.force.x ** 2 + m.wrench.force.y ** 2 + m.wrench.force.z ** 2)),
                             queue_size=1)
        self.mug = None  # the mug's newest position in the world (its TF, child frame "mug")
        rospy.Subscriber("/tf", TFMessage, self.on_tf, queue_size=100)

    def on_tf(self, message):
        for transform in message.transforms:
            if transform.child_frame_id == "mug":
                self.mug = transform.transform.translation

    def near(self, targets, tolerance):
        return all(name in self.proxy and math.dist(self.proxy[name], target) < tolerance
                   for name, target in zip(FINGERS, targets))

    def test_the_example_presses_the_mug_from_outside(self):
        commands = documented_commands()
        self.assertEqual(len(commands), 2, "docs/devices.md: the approach and the press")
        approach, press = poses_of(commands[0]), poses_of(commands[1])
        self.assertEqual(len(approach), 3)
        self.assertEqual(len(press), 3)

        first = subprocess.Popen(commands[0], stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)
        try:
            self.wait_for(lambda: self.near(approach, 0.005), 40, "every finger beside the mug")
        finally:
            first.send_signal(signal.SIGINT)
            first.wait(timeout=20)
        second = subprocess.Popen(commands[1], stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)
        try:
            self.wait_for(lambda: all(self.force.get(name, 0.0) > 0.5 for name in FINGERS), 20,
                          "every finger pressing (0.5 N)")
            self.wait_for(lambda: self.mug is not None, 10, "the mug's TF")
            mug = self.mug
            for name in FINGERS:
                x, y, z = self.proxy[name]
                radial = math.hypot(x - mug.x, y - mug.y)
                print("%s: proxy %.4f m from the mug's axis, z %.4f m, %.2f N" % (name, radial, z, self.force[name]))
                self.assertGreater(radial, MUG_RADIUS, "%s is inside the mug's wall" % name)
                self.assertLess(z - mug.z, MUG_HEIGHT, "%s is above the rim" % name)
                self.assertLess(self.force[name], 10.0, "%s presses too hard" % name)
        finally:
            second.send_signal(signal.SIGINT)
            second.wait(timeout=20)


if __name__ == "__main__":
    rostest.rosrun("god_finger", "pose_source_docs", PoseSourceDocs, sys.argv)
