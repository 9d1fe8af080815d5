#!/usr/bin/python3
"""rostest: rviz renders the demo under Xvfb, and a screenshot shows the yellow contact area
where the finger presses on the ball: near the top of the ball, which the rviz config's
camera puts at the centre of the window, a little above it."""
import os
import subprocess
import sys
import time
import unittest

import rospy
import rostest
from visualization_msgs.msg import MarkerArray
from PIL import Image


def analyse(path):
    """The screenshot's yellow pixels and the ball's light blue ones (every 2nd pixel), in the
    3D view only: right of rviz's Displays panel, between its tool and status bars."""
    image = Image.open(path).convert("RGB")
    width, height = image.size
    yellow = []
    ball = []
    for y in range(int(0.09 * height), int(0.9 * height), 2):
        for x in range(int(0.36 * width), width, 2):
            r, g, b = image.getpixel((x, y))
            if r > 180 and g > 160 and b < 90 and abs(r - g) < 80:
                yellow.append((x, y))
            elif b > 150 and b > r + 25 and g > r:  # the ball's light blue
                ball.append((x, y))
    return width, height, yellow, ball


class Screenshot(unittest.TestCase):
    def test_contact_area_is_yellow_on_the_ball(self):
        rospy.init_node("screenshot_test")
        display = rospy.get_param("~display", ":97")
        path = rospy.get_param("~file", "/tmp/god_finger_screenshot.png")
        # Wait until the physics reports a contact area, then until rviz has drawn it: take
        # screenshots until one shows the ball and a contact area on it (rviz in software
        # OpenGL on a loaded machine may take seconds to draw the first frames).
        deadline = time.time() + 60.0
        found = False
        while time.time() < deadline and not found:
            try:
                markers = rospy.wait_for_message("/markers", MarkerArray, timeout=5.0)
            except rospy.ROSException:
                continue
            found = any(m.ns == "contact_areas" and m.action == m.ADD for m in markers.markers)
        self.assertTrue(found, "no contact area in /markers within 60 s")
        deadline = time.time() + 40.0
        while True:
            subprocess.run(["import", "-display", display, "-window", "root", path], check=True)
            width, height, yellow, ball = analyse(path)
            if (len(yellow) > 100 and len(ball) > 1000) or time.time() > deadline:
                break
            time.sleep(0.5)  # polls the display (each screenshot is a full-window capture)
        count = len(yellow)
        cx = sum(p[0] for p in yellow) / max(count, 1) / width
        cy = sum(p[1] for p in yellow) / max(count, 1) / height
        print("screenshot %s: %d yellow pixels (every 2nd), centre at (%.2f, %.2f) of the window" % (path, count, cx, cy))
        self.assertGreater(count, 100, "no yellow contact area in the screenshot %s within 40 s" % path)
        self.assertGreater(len(ball), 1000, "no ball in the screenshot %s within 40 s" % path)
        left = min(p[0] for p in ball) / width
        right = max(p[0] for p in ball) / width
        top = min(p[1] for p in ball) / height
        bottom = max(p[1] for p in ball) / height
        print("ball from (%.2f, %.2f) to (%.2f, %.2f) of the window" % (left, top, right, bottom))
        # The finger presses on the top of the ball: the area sits on the ball's upper rim,
        # in the middle of it from left to right.
        middle = 0.5 * (left + right)
        self.assertLess(abs(cx - middle), 0.2 * (right - left), "the contact area is not above the ball's middle")
        self.assertTrue(top - 0.1 * (bottom - top) < cy < top + 0.35 * (bottom - top),
                        "the contact area (y %.2f) is not on the top of the ball (%.2f to %.2f)" % (cy, top, bottom))


if __name__ == "__main__":
    rostest.rosrun("god_finger", "screenshot", Screenshot, sys.argv)
