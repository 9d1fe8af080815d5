#!/usr/bin/python3
"""rostest (rviz_view.test): scripts/rviz_view's names and rviz's environment, without rviz.
 - Every config's god_finger display is named for the device backend and the contact model in
   use, read from the master as the physics has it (/servo/model: god_object here, or
   /physics/model in the topic topologies): "interactive: god_object (...)", never
   "fake: god_finger (...)" for another backend or model; the interactive handle's display only
   with the interactive backend.
 - rviz's lookup at start, `rospack plugins --attrib=ogre_media_path media_export`, fails on a
   system without media_export (Debian's: "[rospack] Error: no such package media_export") and
   succeeds, printing no error, in the environment rviz_view gives rviz."""
import glob
import importlib.machinery
import importlib.util
import os
import subprocess
import sys
import tempfile
import unittest

import rospkg
import rospy
import rostest
import yaml

PACKAGE = rospkg.RosPack().get_path("god_finger")


def rviz_view():
    """scripts/rviz_view as a module (it has no .py)."""
    loader = importlib.machinery.SourceFileLoader("rviz_view", os.path.join(PACKAGE, "scripts", "rviz_view"))
    spec = importlib.util.spec_from_loader("rviz_view", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


def display_names(config):
    return [display["Name"] for display in config["Visualization Manager"]["Displays"]]


class RvizView(unittest.TestCase):
    def setUp(self):
        rospy.init_node("rviz_view_test")
        self.view = rviz_view()

    def test_displays_are_named_for_the_backend_and_the_model_in_use(self):
        model = self.view.model_in_use(self.view.master_param)
        self.assertEqual(model, "god_object")  # /servo/model, as the physics starts with it
        # /physics/model in the topic topologies; neither: the config's own word kept.
        self.assertEqual(self.view.model_in_use({"/physics/model": "soft_finger"}.get), "soft_finger")
        self.assertIsNone(self.view.model_in_use({}.get))
        configs = sorted(glob.glob(os.path.join(PACKAGE, "config", "*.rviz")))
        self.assertGreater(len(configs), 10)
        for path in configs:
            with open(path) as handle:
                has_handle = any(display.get("Class") == "rviz/InteractiveMarkers"
                                 for display in yaml.safe_load(handle)["Visualization Manager"]["Displays"])
            for device in ("interactive", "fake", "fake_hand"):
                with open(path) as handle:
                    named = display_names(self.view.named_for(yaml.safe_load(handle), device, model))
                markers = [name for name in named if name.startswith(device + ": ")]
                self.assertEqual(len(markers), 1, "%s, %s: %s" % (os.path.basename(path), device, named))
                self.assertTrue(markers[0].startswith(device + ": god_object"), markers[0])
                self.assertNotIn("god_finger", markers[0])
                self.assertEqual("interactive handle" in named, device == "interactive" and has_handle, named)
        with open(os.path.join(PACKAGE, "config", "table_ball.rviz")) as handle:
            named = display_names(self.view.named_for(yaml.safe_load(handle), "interactive", "god_object"))
        print("rviz_view: table_ball.rviz's displays with device:=interactive model:=god_object: %s" % named)
        self.assertIn("interactive: god_object (scene, proxies, contact areas)", named)

    def test_rviz_finds_media_export_in_the_environment_it_is_given(self):
        lookup = ["rospack", "plugins", "--attrib=ogre_media_path", "media_export"]
        installed = self.view.installed_package("media_export")
        if not installed:
            # The error every rviz start printed on Debian.
            bare = subprocess.run(lookup, stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
            self.assertIn("no such package media_export", bare.stderr)
        folder = tempfile.mkdtemp()
        environment = self.view.rviz_environment(os.environ, folder, self.view.installed_package)
        given = subprocess.run(lookup, stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True,
                               env=environment)
        print("rviz_view: media_export %s; rviz's lookup exits %d, stderr %r"
              % ("installed" if installed else "stood in for", given.returncode, given.stderr))
        self.assertEqual(given.returncode, 0)
        self.assertNotIn("Error", given.stderr)
        if installed:
            self.assertEqual(environment, dict(os.environ))  # nothing stood in for
        else:
            self.assertTrue(environment["ROS_PACKAGE_PATH"].startswith(os.path.join(folder, "packages")))
            # The rest of the path is kept: rviz still finds its own plugins and god_finger.
            found = subprocess.run(["rospack", "find", "god_finger"], stdout=subprocess.PIPE, universal_newlines=True,
                                   env=environment)
            self.assertEqual(found.stdout.strip(), PACKAGE)


if __name__ == "__main__":
    rostest.rosrun("god_finger", "rviz_view", RvizView, sys.argv)
