"""What the Python rostests share: waiting on a condition with a deadline (never sleeping to
synchronise), running a command as a user types it, and dragging the interactive device's rviz
marker as a user does. A mixin for unittest.TestCase."""
import math
import subprocess
import time

import rospy
from diagnostic_msgs.msg import DiagnosticArray
from visualization_msgs.msg import InteractiveMarkerFeedback


def handle_height(publisher):
    """How far (m) the interactive handle floats above its finger: the marker server's
    parameter NAME/device_marker/handle_height, NAME/device_marker/feedback being `publisher`'s
    topic (the marker's pose is the handle's, the finger is that far below it)."""
    return rospy.get_param(publisher.resolved_name[:-len("feedback")] + "handle_height")


def drag_marker(publisher, start, x, y, z, seconds):
    """Drags the interactive device's marker so that its finger goes from `start` (a point,
    device frame, m) to (x, y, z) in 20 mouse events over `seconds`, as rviz sends them on
    NAME/device_marker/feedback (the handle's poses: the finger's raised by handle_height)."""
    above = handle_height(publisher)
    for k in range(1, 21):
        feedback = InteractiveMarkerFeedback()
        feedback.header.frame_id = "finger_device"
        feedback.client_id = "/rviz/InteractiveMarkers"
        feedback.marker_name = "hand"
        feedback.event_type = InteractiveMarkerFeedback.POSE_UPDATE
        s = k / 20.0
        feedback.pose.position.x = start.x + s * (x - start.x)
        feedback.pose.position.y = start.y + s * (y - start.y)
        feedback.pose.position.z = start.z + s * (z - start.z) + above
        feedback.pose.orientation.w = 1.0
        publisher.publish(feedback)
        # Paces the drag (mouse events spread over `seconds`, as a hand drags), not a
        # synchronisation: the tests wait on what the drag does.
        time.sleep(seconds / 20.0)


def turn_marker(publisher, position, angle, seconds):
    """Turns the interactive device's marker, its finger held at `position` (a point, device
    frame), from rest to `angle` (rad) about its x (the finger's own axis: its ring rotate_x) in
    20 mouse events over `seconds`, as rviz sends them."""
    above = handle_height(publisher)
    for k in range(1, 21):
        feedback = InteractiveMarkerFeedback()
        feedback.header.frame_id = "finger_device"
        feedback.client_id = "/rviz/InteractiveMarkers"
        feedback.marker_name = "hand"
        feedback.control_name = "rotate_x"
        feedback.event_type = InteractiveMarkerFeedback.POSE_UPDATE
        feedback.pose.position.x = position.x
        feedback.pose.position.y = position.y
        feedback.pose.position.z = position.z + above
        half = 0.5 * angle * k / 20.0
        feedback.pose.orientation.w = math.cos(half)
        feedback.pose.orientation.x = math.sin(half)
        publisher.publish(feedback)
        time.sleep(seconds / 20.0)  # paces the turn, as drag_marker


class RosTestSupport:
    def wait_for(self, condition, seconds, what):
        """Polls `condition` until it holds; fails naming `what` after `seconds`."""
        deadline = time.time() + seconds
        while not condition() and time.time() < deadline:
            time.sleep(0.05)  # polls within the deadline
        self.assertTrue(condition(), "waited %.0f s for %s" % (seconds, what))

    def watch_finger_statuses(self, fingers):
        """A dict finger -> the servo's newest diagnostic status for `finger hand/NAME` (on
        /diagnostics), kept up to date from now on."""
        statuses = {}

        def on_diagnostics(array):
            for status in array.status:
                for name in fingers:
                    if status.name.endswith(": finger hand/" + name):
                        statuses[name] = status

        rospy.Subscriber("/diagnostics", DiagnosticArray, on_diagnostics, queue_size=10)
        return statuses

    def run_command(self, command):
        """Runs `command` (a list) as a user types it; asserts it exits 0; returns its output."""
        done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=60,
                              universal_newlines=True)
        self.assertEqual(done.returncode, 0, "%s failed:\n%s" % (" ".join(command), done.stdout))
        return done.stdout
