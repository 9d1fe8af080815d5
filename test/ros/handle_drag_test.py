#!/usr/bin/python3
"""rostest: a person drags the interactive handle onto and into the ball with the mouse, from
the demo's default view (rviz under Xvfb, the mouse moved by xdotool, as a hand moves it).

The handle's grab ball is the only magenta in the view: the test finds it in a screenshot,
presses the left button on it and moves the mouse down in small steps, as a person does, until
the finger touches the ball (a contact area and a force), then 40 pixels further, into it. It
asserts what the person feels and sees: the finger below the ball's top (8 cm), a force on the
hand, the god-object on the ball's surface, and the yellow contact area visible in the
screenshot (not hidden by the handle's rings)."""
import math
import subprocess
import sys
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import PointStamped, WrenchStamped
from god_finger.msg import ContactAreaArray, DeviceState
from PIL import Image
from ros_test_support import RosTestSupport

BALL_CENTRE = (0.0, 0.0, 0.04)  # m, world: table_ball's ball, r = 4 cm
BALL_RADIUS = 0.04


def pixels(path, test):
    """The screenshot's pixels (every 2nd) in rviz's 3D view that satisfy `test(r, g, b)`."""
    image = Image.open(path).convert("RGB")
    width, height = image.size
    found = []
    for y in range(int(0.09 * height), int(0.9 * height), 2):
        for x in range(int(0.36 * width), width, 2):
            if test(*image.getpixel((x, y))):
                found.append((x, y))
    return found


def magenta(r, g, b):
    return r > 150 and b > 150 and g < 110


def yellow(r, g, b):
    return r > 180 and g > 160 and b < 90 and abs(r - g) < 80


class HandleDrag(unittest.TestCase, RosTestSupport):
    def setUp(self):
        rospy.init_node("handle_drag_test")
        self.display = rospy.get_param("~display", ":96")
        self.path = rospy.get_param("~file", "/tmp/god_finger_handle_drag.png")
        self.state = None
        self.force = 0.0
        self.areas = 0
        self.proxy = None
        rospy.Subscriber("/finger/device/state", DeviceState, self.on_state, queue_size=10)
        rospy.Subscriber("/finger/feedback", WrenchStamped, self.on_feedback, queue_size=10)
        rospy.Subscriber("/finger/proxy", PointStamped, self.on_proxy, queue_size=10)
        rospy.Subscriber("/contact_areas", ContactAreaArray, self.on_areas, queue_size=10)

    def on_state(self, message):
        self.state = message.position

    def on_feedback(self, message):
        f = message.wrench.force
        self.force = math.sqrt(f.x * f.x + f.y * f.y + f.z * f.z)

    def on_proxy(self, message):
        self.proxy = message.point

    def on_areas(self, message):
        self.areas = len(message.areas)

    def screenshot(self):
        subprocess.run(["import", "-display", self.display, "-window", "root", self.path], check=True)
        return self.path

    def mouse(self, *arguments):
        subprocess.run(["xdotool"] + [str(a) for a in arguments], check=True,
                       env={"DISPLAY": self.display, "PATH": "/usr/bin:/bin"})

    def test_the_mouse_drags_the_finger_onto_and_into_the_ball(self):
        self.wait_for(lambda: self.state is not None, 60.0, "the interactive device's state")
        # rviz draws the handle once it has its marker: poll screenshots for the grab ball.
        grab = []
        deadline = time.time() + 60.0
        while len(grab) < 10 and time.time() < deadline:
            grab = pixels(self.screenshot(), magenta)
            if len(grab) < 10:
                time.sleep(0.5)  # polls the display (each screenshot is a full-window capture)
        self.assertGreaterEqual(len(grab), 10, "no handle (magenta grab ball) in %s within 60 s" % self.path)
        x = int(sum(p[0] for p in grab) / len(grab))
        y = int(sum(p[1] for p in grab) / len(grab))
        start_z = self.state.z
        print("handle_drag: grab ball at (%d, %d), finger at z %.4f m" % (x, y, start_z))
        self.mouse("mousemove", x, y)
        self.mouse("mousedown", 1)
        touched_at = None
        for step in range(1, 121):  # at most 360 px down, 3 px a mouse event
            self.mouse("mousemove", x, y + 3 * step)
            time.sleep(0.03)  # paces the mouse as a hand moves it (about 100 px/s), not a synchronisation
            if touched_at is None and self.areas > 0 and self.force > 0.5:
                touched_at = step
            if touched_at is not None and step >= touched_at + 13:  # 40 px further, into the ball
                break
        self.mouse("mouseup", 1)
        self.assertIsNotNone(touched_at, "the finger never touched the ball (finger at z %.4f m)" % self.state.z)
        self.wait_for(lambda: self.force > 1.0 and self.areas == 1, 10.0,
                      "a press on the ball after the drag (%.2f N, %d areas)" % (self.force, self.areas))
        # The finger (the device) is inside the ball; the god-object stays on its surface.
        finger = (self.state.x, self.state.y, self.state.z)
        finger_depth = BALL_RADIUS - math.dist(finger, BALL_CENTRE)
        proxy_gap = math.dist((self.proxy.x, self.proxy.y, self.proxy.z), BALL_CENTRE) - BALL_RADIUS
        print("handle_drag: touched after %d px; finger at (%.4f, %.4f, %.4f) m, %.1f mm inside the ball, "
              "god-object %.2f mm off its surface, %.2f N on the hand"
              % (3 * touched_at, finger[0], finger[1], finger[2], 1e3 * finger_depth, 1e3 * proxy_gap, self.force))
        self.assertLess(self.state.z, start_z - 0.03, "the drag moved the finger down")
        self.assertGreater(finger_depth, 0.0, "the finger was dragged into the ball")
        self.assertTrue(0.0 < proxy_gap < 0.01, "the god-object stays on the ball, outside it")
        # What the person sees: the contact area, yellow, not hidden by the handle.
        area = []
        deadline = time.time() + 30.0
        while len(area) < 20 and time.time() < deadline:
            area = pixels(self.screenshot(), yellow)
            if len(area) < 20:
                time.sleep(0.5)  # polls the display
        print("handle_drag: %d yellow pixels (every 2nd) of contact area in %s" % (len(area), self.path))
        self.assertGreaterEqual(len(area), 20, "the contact area is not visible in %s" % self.path)


if __name__ == "__main__":
    rostest.rosrun("god_finger", "handle_drag", HandleDrag, sys.argv)
