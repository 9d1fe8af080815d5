#!/usr/bin/python3
"""rostest (no nodes): scripts/demo's outcome words (scripts/experiment_outcome) for real
god_finger_experiment results: the god-object's lift drops as the paper says and is named so,
the god-finger's holds, a hand_grasp's fall after the release is the intended result, and a
metric that is 0 in all but rounding prints as 0."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

import rospkg
import rostest
from roslib.packages import find_node

PACKAGE = rospkg.RosPack().get_path("god_finger")
SCRIPT = os.path.join(PACKAGE, "scripts", "experiment_outcome")


def outcome(scenario, model):
    tool = find_node("god_finger", "god_finger_experiment")
    if not tool:
        raise AssertionError("god_finger_experiment not built")
    result = subprocess.run([tool[0], "--scenario", scenario, "--model", model], check=True, capture_output=True,
                            text=True).stdout
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        f.write(result)
    try:
        line = subprocess.run(["/usr/bin/python3", SCRIPT, f.name], check=True, capture_output=True,
                              text=True).stdout.strip()
    finally:
        os.unlink(f.name)
    print(line)
    return json.loads(result)["metrics"], line


class ExperimentOutcome(unittest.TestCase):
    def test_the_lift_says_dropped_or_held(self):
        metrics, line = outcome("lift_one", "god_object")
        self.assertEqual(metrics["dropped"], 1)
        self.assertIn("dropped (the paper's point", line)
        metrics, line = outcome("lift_one", "god_finger")
        self.assertEqual(metrics["dropped"], 0)
        self.assertIn("held, lifted 0.10", line)
        self.assertNotIn("dropped (", line)

    def test_the_grasp_falls_after_the_release_as_intended(self):
        metrics, line = outcome("hand_grasp", "god_finger")
        self.assertEqual(metrics["fell_after_release"], 1)
        self.assertIn("fell after the release, as physics says", line)

    def test_rounding_noise_prints_as_zero(self):
        metrics, line = outcome("pinch_cylinder", "god_finger")
        self.assertLess(abs(metrics["angular_velocity_about_normal_max"]), 1e-12)
        self.assertIn("angular_velocity_about_normal_max 0,", line)
        self.assertIn("no spin about the pinch axis", line)


if __name__ == "__main__":
    rostest.rosrun("god_finger", "experiment_outcome", ExperimentOutcome, sys.argv)
