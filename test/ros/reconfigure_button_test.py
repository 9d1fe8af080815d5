#!/usr/bin/python3
"""rostest: the device's button 0 cycles the model inside the servo loop (reconfigure_button.test:
pressed once, god_finger -> soft_finger); dynamic_reconfigure then shows soft_finger, and a
later `dynparam set /servo r_max 0.006` keeps it (it once switched the model back)."""
import subprocess
import sys
import unittest

import dynamic_reconfigure.client
import rospy
import rostest
from ros_test_support import RosTestSupport
from diagnostic_msgs.msg import DiagnosticArray


class ReconfigureButton(RosTestSupport, unittest.TestCase):
    def setUp(self):
        rospy.init_node("reconfigure_button_test")
        self.model = None
        self.diagnostics = 0
        rospy.Subscriber("/diagnostics", DiagnosticArray, self.on_diagnostics, queue_size=10)

    def on_diagnostics(self, message):
        for status in message.status:
            for pair in status.values:
                if pair.key == "contact_model":
                    self.model = pair.value
                    self.diagnostics += 1


    def test_the_button_model_stays_through_a_reconfiguration(self):
        client = dynamic_reconfigure.client.Client("/servo", timeout=30)
        self.wait_for(lambda: self.model == "soft_finger", 30.0, "the button's soft_finger in /diagnostics")
        self.wait_for(lambda: client.get_configuration(timeout=5)["model"] == "soft_finger", 5.0,
                      "the reconfiguration server to show the button's soft_finger")
        done = subprocess.run(["rosrun", "dynamic_reconfigure", "dynparam", "set", "/servo", "r_max", "0.006"],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=60, universal_newlines=True)
        self.assertEqual(done.returncode, 0, done.stdout)
        self.wait_for(lambda: abs(client.get_configuration(timeout=5)["r_max"] - 0.006) < 1e-9, 5.0,
                      "the reconfiguration server to show r_max 6 mm")
        seen = self.diagnostics
        self.wait_for(lambda: self.diagnostics >= seen + 2, 10.0, "the diagnostics after r_max 6 mm")
        self.assertEqual(self.model, "soft_finger", "a change of r_max switched the model back")
        self.assertEqual(client.get_configuration(timeout=5)["model"], "soft_finger")
        print("button 0 -> soft_finger, dynparam r_max 6 mm -> model %s" % self.model)


if __name__ == "__main__":
    rostest.rosrun("god_finger", "reconfigure_button", ReconfigureButton, sys.argv)
