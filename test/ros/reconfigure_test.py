#!/usr/bin/python3
"""rostest: dynamic_reconfigure of the simulation (~node: the servo node by default, the
physics node in the topic topologies) while it runs. The finger presses on the
ball; a smaller r_max shrinks the published contact area at once; the model switches; a bad
walk variant is refused and the previous one stays."""
import sys
import time
import unittest

import dynamic_reconfigure.client
import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray
from god_finger.msg import ContactAreaArray


class Reconfigure(unittest.TestCase):
    def setUp(self):
        rospy.init_node("reconfigure_test")
        self.radius = None
        self.model = None
        rospy.Subscriber("/contact_areas", ContactAreaArray, self.on_areas, queue_size=10)
        rospy.Subscriber("/diagnostics", DiagnosticArray, self.on_diagnostics, queue_size=10)

    def on_areas(self, message):
        if message.areas:
            self.radius = message.areas[0].radius

    def on_diagnostics(self, message):
        for status in message.status:
            for pair in status.values:
                if pair.key == "contact_model":
                    self.model = pair.value

    def wait_for(self, condition, seconds, what):
        deadline = time.time() + seconds
        while not condition() and time.time() < deadline:
            time.sleep(0.05)
        self.assertTrue(condition(), "waited %.0f s for %s" % (seconds, what))

    def test_parameters_change_while_running(self):
        client = dynamic_reconfigure.client.Client(rospy.get_param("~node", "/servo"), timeout=30)
        self.wait_for(lambda: self.radius is not None and self.radius > 0.009, 30.0, "a pressing contact area")
        before = self.radius
        config = client.update_configuration({"r_max": 0.004})
        self.assertAlmostEqual(config["r_max"], 0.004)
        self.wait_for(lambda: self.radius is not None and self.radius <= 0.004, 5.0, "the area to shrink")
        print("reconfigure: radius %.2f mm -> %.2f mm with r_max 10 -> 4 mm" % (1e3 * before, 1e3 * self.radius))
        client.update_configuration({"model": "god_object"})
        self.wait_for(lambda: self.model == "god_object", 5.0, "the model in /diagnostics")
        refused = client.update_configuration({"walk": "sideways"})
        self.assertEqual(refused["walk"], "unfold")
        self.assertAlmostEqual(refused["r_max"], 0.004)


if __name__ == "__main__":
    rostest.rosrun("god_finger", "reconfigure", Reconfigure, sys.argv)
