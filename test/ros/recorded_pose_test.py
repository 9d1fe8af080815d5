#!/usr/bin/python3
"""rostest (recorded_pose.test): a recording made before NAME/interface_pose still drives the
physics as a 3-DOF finger. The physics node runs alone. A pose on /finger/pose with an
orientation (what the nodes now send there for tools: the identity for a 3-DOF finger) is not
taken: the first proxy appears where the 3-DOF pose sent after them puts it. A bag whose /finger/pose holds a 3-DOF finger's all-zero quaternion
(the format before), written here and played with `rosbag play`, moves the proxy onto the ball:
the finger presses (force on the hand, a contact area) and is drawn as a 3-DOF finger (pulp
down, world x). Then the first /finger/interface_pose takes over: /finger/pose is no longer
taken, even with the all-zero quaternion."""
import math
import os
import subprocess
import sys
import tempfile
import time
import unittest

import rosbag
import rospy
import rostest
from geometry_msgs.msg import PointStamped, PoseStamped, WrenchStamped
from god_finger.msg import ContactAreaArray, InterfacePose
from ros_test_support import RosTestSupport
from visualization_msgs.msg import MarkerArray

BALL_TOP = 0.08  # m: table_ball's ball, r 4 cm at z 4 cm


class RecordedPose(RosTestSupport, unittest.TestCase):
    def setUp(self):
        rospy.init_node("recorded_pose_test")
        self.proxy = None
        self.first_proxy_z = None
        self.force = 0.0
        self.areas = 0
        self.nail = None  # the fingertip's nail marker's orientation (w, x, y, z)
        rospy.Subscriber("/finger/proxy", PointStamped, self.on_proxy, queue_size=10)
        rospy.Subscriber("/finger/feedback", WrenchStamped, self.on_feedback, queue_size=10)
        rospy.Subscriber("/contact_areas", ContactAreaArray, self.on_areas, queue_size=10)
        rospy.Subscriber("/markers", MarkerArray, self.on_markers, queue_size=10)
        self.poses = rospy.Publisher("/finger/pose", PoseStamped, queue_size=100)
        self.interface_poses = rospy.Publisher("/finger/interface_pose", InterfacePose, queue_size=100)

    def on_proxy(self, message):
        self.proxy = message.point
        if self.first_proxy_z is None:
            self.first_proxy_z = message.point.z

    def on_feedback(self, message):
        f = message.wrench.force
        self.force = math.sqrt(f.x * f.x + f.y * f.y + f.z * f.z)

    def on_areas(self, message):
        self.areas = len(message.areas)

    def on_markers(self, message):
        for marker in message.markers:
            if marker.ns == "fingertips" and marker.type == marker.CUBE and marker.action == marker.ADD:
                q = marker.pose.orientation
                self.nail = (q.w, q.x, q.y, q.z)

    def pose(self, z, w):
        pose = PoseStamped()
        pose.header.stamp = rospy.Time.now()
        pose.header.frame_id = "world"
        pose.pose.position.z = z
        pose.pose.orientation.w = w
        return pose

    def write_old_bag(self, path):
        """A 3-DOF finger's /finger/pose as recorded before interface_pose: all-zero quaternions,
        at 1 kHz, from 4 cm above the ball down to 5 mm into it over 1 s, then held 3 s."""
        start = rospy.Time.now()
        with rosbag.Bag(path, "w") as bag:
            for k in range(4000):
                z = BALL_TOP + 0.04 - 0.045 * min(1.0, k / 1000.0)
                stamp = start + rospy.Duration(k * 1e-3)
                pose = self.pose(z, 0.0)
                pose.header.stamp = stamp
                pose.header.seq = k + 1
                bag.write("/finger/pose", pose, stamp)

    def test_an_old_recording_drives_a_three_dof_finger_until_interface_poses_come(self):
        self.wait_for(lambda: self.poses.get_num_connections() > 0 and self.interface_poses.get_num_connections() > 0,
                      30.0, "the physics to subscribe to /finger/pose and /finger/interface_pose")
        # A tool's pose (an orientation: what the nodes now publish on /finger/pose) is not taken.
        for _ in range(200):
            self.poses.publish(self.pose(0.2, 1.0))
            time.sleep(0.005)  # paces the poses as a 200 Hz source
        # Then one 3-DOF pose (taken) elsewhere: the physics takes a topic's messages in order, so
        # the first proxy it publishes is at this pose if, and only if, it took none of the above.
        marker_z = BALL_TOP + 0.04
        self.poses.publish(self.pose(marker_z, 0.0))
        self.wait_for(lambda: self.first_proxy_z is not None, 10.0, "a proxy from the 3-DOF pose")
        self.assertAlmostEqual(self.first_proxy_z, marker_z, delta=0.002,
                               msg="the physics took a /finger/pose with an orientation (its proxy appeared at "
                               "z %.4f m, not at the 3-DOF pose's %.4f m)" % (self.first_proxy_z, marker_z))
        bag = os.path.join(tempfile.mkdtemp(), "recorded_before_interface_pose.bag")
        self.write_old_bag(bag)
        subprocess.run(["rosbag", "play", "--quiet", bag], stdin=subprocess.DEVNULL, check=True, timeout=60)
        self.wait_for(lambda: self.force > 1.0 and self.areas == 1, 10.0, "the recorded finger pressing on the ball")
        self.wait_for(lambda: self.nail is not None, 5.0, "the fingertip's markers")
        w, x, y, z = self.nail
        print("recorded_pose: an old bag's 3-DOF finger presses %.2f N, proxy at z %.4f m, nail (%.3f, %.3f, %.3f, %.3f)"
              % (self.force, self.proxy.z, w, x, y, z))
        # Drawn as a 3-DOF finger: pulp down along world x (w 0, x 1), not turned to the identity.
        self.assertAlmostEqual(abs(x), 1.0, places=6)
        self.assertAlmostEqual(w, 0.0, places=6)
        self.assertLess(self.proxy.z, BALL_TOP + 0.0035)
        # The first interface pose takes over: a 3-DOF finger 3 cm above the ball.
        for _ in range(300):
            message = InterfacePose()
            message.header.stamp = rospy.Time.now()
            message.header.frame_id = "world"
            message.pose.position.z = BALL_TOP + 0.03
            message.pose.orientation.w = 1.0
            message.has_orientation = False
            self.interface_poses.publish(message)
            time.sleep(0.003)  # paces them as a device's states
        self.wait_for(lambda: abs(self.proxy.z - (BALL_TOP + 0.03)) < 2e-3, 10.0, "the proxy at the interface pose")
        self.wait_for(lambda: self.poses.get_num_connections() == 0, 5.0,
                      "the physics to stop taking /finger/pose")
        self.assertAlmostEqual(abs(self.nail[1]), 1.0, places=6)  # still 3-DOF


if __name__ == "__main__":
    rostest.rosrun("god_finger", "recorded_pose", RecordedPose, sys.argv)
