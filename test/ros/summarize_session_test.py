#!/usr/bin/python3
"""scripts/summarize_session on small bags written here (/tf of the ball, /diagnostics): a ball
that left the world is reported as "left the world at t = 52.0 s", from the servo's left_world
diagnostics (put back at its start) or, in a recording from before world bounds, from its fall;
never as the distance it fell; a ball that stayed is reported by how far it moved."""
import os
import subprocess
import sys
import tempfile
import unittest

import rosbag
import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus, KeyValue
from geometry_msgs.msg import TransformStamped
from tf2_msgs.msg import TFMessage

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "summarize_session")
START = 100.0  # s, the bag's first stamp


def ball_at(x, z):
    transform = TransformStamped()
    transform.header.frame_id = "world"
    transform.child_frame_id = "ball"
    transform.transform.translation.x = x
    transform.transform.translation.z = z
    transform.transform.rotation.w = 1.0
    return TFMessage(transforms=[transform])


def servo_diagnostics(left_world):
    status = DiagnosticStatus(name="/servo: servo loop", values=[KeyValue("left_world", left_world)])
    return DiagnosticArray(status=[status])


class SummarizeSession(unittest.TestCase):
    def summarize(self, messages):
        """Writes (seconds after START, topic, message) to a bag; returns the script's output."""
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "session.bag")
            with rosbag.Bag(path, "w") as bag:
                for seconds, topic, message in messages:
                    bag.write(topic, message, rospy.Time.from_sec(START + seconds))
            done = subprocess.run([sys.executable, SCRIPT, path], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                  universal_newlines=True, timeout=60)
        self.assertEqual(done.returncode, 0, done.stdout)
        return done.stdout

    def test_a_ball_that_fell_forever_left_the_world_at_its_fall(self):
        # No world bounds (an old recording): it rolls at 12 mm/s, leaves the table at 50 s and
        # falls for ever (g t^2 / 2 below the table).
        messages = []
        for tenth in range(0, 3600):
            t = tenth / 10.0
            x = 0.04 + 0.012 * min(t, 50.0)
            z = 0.04 - (4.905 * (t - 50.0) ** 2 if t > 50.0 else 0.0)
            messages.append((t, "/tf", ball_at(x, z)))
        output = self.summarize(messages)
        # 1 m below its start 0.45 s after leaving the table (the first tenth past it: 50.5 s)
        self.assertIn("ball: left the world at t = 50.5 s (fell more than 1 m below its start)", output)
        self.assertNotIn("moved", output)

    def test_a_ball_the_world_put_back_left_it_at_the_time_the_servo_said(self):
        messages = [(0.0, "/tf", ball_at(0.0, 0.04)), (1.0, "/diagnostics", servo_diagnostics("none")),
                    (52.5, "/diagnostics", servo_diagnostics("ball (1) at 52.013 s")),
                    (60.0, "/tf", ball_at(0.01, 0.04))]
        output = self.summarize(messages)
        self.assertIn("ball: left the world at t = 52.0 s (put back at its start); moved 10.0 mm, turned 0.000 rad"
                      " in all", output)

    def test_a_ball_caught_twice_says_so_and_other_bodies_do_not_count(self):
        messages = [(0.0, "/tf", ball_at(0.0, 0.04)),
                    (70.0, "/diagnostics", servo_diagnostics("box_3 (1) at 20.000 s; ball (2) at 61.250 s")),
                    (71.0, "/tf", ball_at(0.0, 0.04))]
        output = self.summarize(messages)
        self.assertIn("ball: left the world at t = 61.2 s, 2 times (put back at its start)", output)

    def test_a_ball_that_stayed_is_reported_by_its_motion(self):
        messages = [(0.0, "/tf", ball_at(0.0, 0.04)), (5.0, "/diagnostics", servo_diagnostics("box_3 (1) at 2.000 s")),
                    (10.0, "/tf", ball_at(0.025, 0.04))]
        output = self.summarize(messages)
        self.assertIn("ball: moved 25.0 mm, turned 0.000 rad", output)
        self.assertNotIn("left the world", output)


if __name__ == "__main__":
    rostest.rosrun("god_finger", "summarize_session", SummarizeSession, sys.argv)
