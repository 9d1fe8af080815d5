#!/usr/bin/python3
"""rostest: god_finger_delay relays /link_in to /link_out with 50 ms of delay and 20 % loss
(delay_line.test). 400 stamped points at 200 Hz go in: about 80 % come out (within 4 binomial
standard errors), in the order they went in, none sooner than 50 ms (less the 1 ms release
timer's granularity) after it was stamped, and the link's diagnostics count what entered, what
was lost and what came out. The delays' exact schedule is delay_line_test's (C++); here a loose
ceiling only, for a loaded machine. Waits on conditions with deadlines."""
import sys
import time
import unittest

import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import PointStamped
from ros_test_support import RosTestSupport

SENT = 400
DELAY = 0.05  # s
LOSS = 0.2


class DelayLine(RosTestSupport, unittest.TestCase):
    def setUp(self):
        rospy.init_node("delay_line_test")
        self.received = []  # (sequence, delay s)
        self.status = None
        rospy.Subscriber("/link_out", PointStamped, self.on_point, queue_size=1000)
        rospy.Subscriber("/diagnostics", DiagnosticArray, self.on_diagnostics, queue_size=10)

    def on_point(self, message):
        self.received.append((int(message.point.x), (rospy.Time.now() - message.header.stamp).to_sec()))

    def on_diagnostics(self, array):
        for status in array.status:
            if status.name == "delay: /link_in -> /link_out":
                self.status = {pair.key: pair.value for pair in status.values}

    def point(self, sequence):
        point = PointStamped()
        point.header.stamp = rospy.Time.now()
        point.point.x = sequence
        return point

    def quiet(self, entered):
        """The link's lost count once its diagnostics say that `entered` messages entered and none is
        in flight. Waiting for the count itself: a status with nothing in flight may be older than
        the last message sent (diagnostics come once a second), and its counts then short of it."""
        self.wait_for(lambda: self.status is not None and int(self.status["entered"]) == entered and
                      int(self.status["in flight"]) == 0, 20,
                      "the link's diagnostics to count %d entered with nothing in flight" % entered)
        return int(self.status["lost"])

    def test_a_delayed_lossy_link(self):
        publisher = rospy.Publisher("/link_in", PointStamped, queue_size=1000)
        self.wait_for(lambda: publisher.get_num_connections() > 0, 20, "the delay node subscribing to /link_in")
        # The node advertises /link_out with the first message's type: until this test's
        # subscriber is connected to it, what comes out is not heard. Warm up until it is.
        deadline = time.time() + 20
        warm_ups = 0  # every one enters the link: it subscribed before the first
        while not self.received and time.time() < deadline:
            publisher.publish(self.point(-1))
            warm_ups += 1
            time.sleep(0.05)  # paces the warm-up messages (20 Hz), not a synchronisation
        self.assertTrue(self.received, "a warm-up message through the link")
        lost_before = self.quiet(warm_ups)
        rate = rospy.Rate(200)
        for sequence in range(SENT):
            publisher.publish(self.point(sequence))
            rate.sleep()
        lost = self.quiet(warm_ups + SENT) - lost_before
        # The test's own points only: a warm-up point may still be on its way from the link.
        self.wait_for(lambda: sum(1 for sequence, _ in self.received if sequence >= 0) == SENT - lost, 10,
                      "%d messages out of the link" % (SENT - lost))
        self.received = [(sequence, delay) for sequence, delay in self.received if sequence >= 0]
        sequences = [sequence for sequence, _ in self.received]
        delays = [delay for _, delay in self.received]
        print("delay line: %d of %d through (%d lost), delay min %.4f s, mean %.4f s, max %.4f s" %
              (len(self.received), SENT, lost, min(delays), sum(delays) / len(delays), max(delays)))
        standard_error = (SENT * LOSS * (1 - LOSS)) ** 0.5
        self.assertLess(abs(lost - SENT * LOSS), 4 * standard_error)
        self.assertEqual(sequences, sorted(sequences), "first in, first out")
        self.assertGreaterEqual(min(delays), DELAY - 0.0015)
        self.assertLess(sum(delays) / len(delays), DELAY + 0.05)  # a loose ceiling: a loaded machine


if __name__ == "__main__":
    rostest.rosrun("god_finger", "delay_line", DelayLine, sys.argv)
