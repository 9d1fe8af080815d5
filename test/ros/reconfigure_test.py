#!/usr/bin/python3
"""rostest: dynamic_reconfigure of the simulation (~node: the servo node by default, the
physics node in the topic topologies) while it runs. The finger presses on the
ball; a smaller r_max shrinks the published contact area at once; the model switches; a bad
walk variant is refused and the previous one stays; the pad solver switches (its diagnostics
value), a bad one is refused. Then the user's sequence of issue 18: the
set_contact_model service switches the model, and a later `dynparam set` of r_max keeps it (the
server shows the model in force, and one entry's change resets no other)."""
import sys
import unittest

import dynamic_reconfigure.client
import rospy
import rostest
from ros_test_support import RosTestSupport
from diagnostic_msgs.msg import DiagnosticArray
from god_finger.msg import ContactAreaArray


class Reconfigure(RosTestSupport, unittest.TestCase):
    def setUp(self):
        rospy.init_node("reconfigure_test")
        self.radius = None
        self.model = None
        self.diagnostics = 0  # messages that carried a contact model
        self.pad_solver = None
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
                    self.diagnostics += 1
                if pair.key == "pad_solver":
                    self.pad_solver = pair.value


    def wait_for_diagnostics(self, count, what):
        """Waits for `count` more diagnostics messages (1 Hz): they show the loop after what was sent."""
        seen = self.diagnostics
        self.wait_for(lambda: self.diagnostics >= seen + count, 10.0, what)

    def test_parameters_change_while_running(self):
        node = rospy.get_param("~node", "/servo")
        client = dynamic_reconfigure.client.Client(node, timeout=30)
        self.wait_for(lambda: self.radius is not None and self.radius > 0.009, 30.0, "a pressing contact area")
        before = self.radius
        # Issue 18: one range per parameter; r_max above the old 5 cm slider end is taken as it is.
        wide = client.update_configuration({"r_max": 0.2})
        self.assertAlmostEqual(wide["r_max"], 0.2)
        config = client.update_configuration({"r_max": 0.004})
        self.assertAlmostEqual(config["r_max"], 0.004)
        self.wait_for(lambda: self.radius is not None and self.radius <= 0.004, 5.0, "the area to shrink")
        print("reconfigure: radius %.2f mm -> %.2f mm with r_max 10 -> 4 mm" % (1e3 * before, 1e3 * self.radius))
        client.update_configuration({"model": "god_object"})
        self.wait_for(lambda: self.model == "god_object", 5.0, "the model in /diagnostics")
        refused = client.update_configuration({"walk": "sideways"})
        self.assertEqual(refused["walk"], "unfold")
        self.assertAlmostEqual(refused["r_max"], 0.004)
        self.assertEqual(refused["model"], "god_object")

        # Issue 18: the pad solver changes live too, and a bad one is refused.
        self.wait_for(lambda: self.pad_solver == "constraint", 5.0, "the default pad solver in /diagnostics")
        self.assertEqual(client.update_configuration({"pad_solver": "points"})["pad_solver"], "points")
        self.wait_for(lambda: self.pad_solver == "points", 5.0, "pad_solver points in /diagnostics")
        refused = client.update_configuration({"pad_solver": "sideways"})
        self.assertEqual(refused["pad_solver"], "points")
        self.run_command(["rosrun", "dynamic_reconfigure", "dynparam", "set", node, "pad_solver", "constraint"])
        self.wait_for(lambda: self.pad_solver == "constraint", 5.0, "pad_solver constraint in /diagnostics")
        self.assertEqual(client.get_configuration(timeout=5)["pad_solver"], "constraint")

        # Issue 18: the service switches the model, and a later change of r_max keeps it.
        client.update_configuration({"model": "god_finger"})
        self.wait_for(lambda: self.model == "god_finger", 5.0, "god_finger in /diagnostics")
        answer = self.run_command(["rosservice", "call", "/set_contact_model", "god_object"])
        self.assertIn("success: True", answer)
        self.wait_for(lambda: self.model == "god_object", 5.0, "the service's god_object in /diagnostics")
        self.wait_for(lambda: client.get_configuration(timeout=5)["model"] == "god_object", 5.0,
                      "the reconfiguration server to show the service's god_object")
        self.run_command(["rosrun", "dynamic_reconfigure", "dynparam", "set", node, "r_max", "0.006"])
        self.wait_for(lambda: abs(client.get_configuration(timeout=5)["r_max"] - 0.006) < 1e-9, 5.0,
                      "the reconfiguration server to show r_max 6 mm")
        self.wait_for_diagnostics(2, "the diagnostics after r_max 6 mm")
        self.assertEqual(self.model, "god_object", "a change of r_max switched the model back")
        config = client.get_configuration(timeout=5)
        self.assertEqual(config["model"], "god_object")
        self.assertAlmostEqual(config["r_max"], 0.006)
        self.assertEqual(config["walk"], "unfold")
        print("reconfigure: service -> god_object, dynparam r_max 6 mm -> model %s, config model %s"
              % (self.model, config["model"]))


if __name__ == "__main__":
    rostest.rosrun("god_finger", "reconfigure", Reconfigure, sys.argv)
