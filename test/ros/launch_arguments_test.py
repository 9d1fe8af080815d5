#!/usr/bin/python3
"""rostest: the launches' arguments as a user types them.

- Every `roslaunch god_finger FILE.launch name:=value` in README.md and docs/*.md names a launch
  that exists and only arguments that launch declares (roslaunch ignores an unknown one without
  a word), and each named choice (topology, device, scene, model, script) is a valid one.
- A wrong topology, device, scene, model or script stops roslaunch before anything starts, with
  one line naming the value and listing the valid ones (launch/argument_check.launch).
- argument_check.launch's lists are the code's: the device registry's backends, the contact
  models god_finger_experiment lists, the scenes in urdf/scenes and the scripts in config/scripts.
Needs no master: roslaunch --nodes only loads the launch."""
import glob
import os
import re
import subprocess
import sys
import unittest
import xml.dom.minidom

import rospkg
import rostest
from roslib.packages import find_node

PACKAGE = rospkg.RosPack().get_path("god_finger")
CHOICES = ("topology", "device", "scene", "model", "script")
COMMAND = re.compile(r"roslaunch\s+god_finger\s+([\w.]+\.launch)((?:\s+\w+:=[^\s`]+)*)")


def check_lists():
    """argument_check.launch's lists: {choice: [values]}."""
    document = xml.dom.minidom.parse(os.path.join(PACKAGE, "launch", "argument_check.launch"))
    values = {a.getAttribute("name"): a.getAttribute("value").split()
              for a in document.getElementsByTagName("arg") if a.hasAttribute("value")}
    plural = {"topology": "topologies", "device": "devices", "scene": "scenes", "model": "models",
              "script": "scripts"}
    return {choice: values[plural[choice]] for choice in CHOICES}


def declared_args(launch):
    """The arguments a user can set on `launch`: its top-level <arg> tags without a fixed value."""
    document = xml.dom.minidom.parse(os.path.join(PACKAGE, "launch", launch))
    root = document.documentElement
    return {n.getAttribute("name") for n in root.childNodes
            if n.nodeType == n.ELEMENT_NODE and n.tagName == "arg" and not n.hasAttribute("value")}


def documented_commands():
    """(page, launch, {arg: value}) for every roslaunch command of the package in the docs."""
    pages = [os.path.join(PACKAGE, "README.md")] + sorted(glob.glob(os.path.join(PACKAGE, "docs", "*.md")))
    commands = []
    for page in pages:
        with open(page) as f:
            text = f.read()
        for match in COMMAND.finditer(text):
            args = dict(token.split(":=", 1) for token in match.group(2).split())
            commands.append((os.path.relpath(page, PACKAGE), match.group(1), args))
    return commands


def roslaunch_nodes(launch, args):
    return subprocess.run(["roslaunch", "--nodes", "god_finger", launch] + args, capture_output=True, text=True,
                          timeout=60)


class LaunchArguments(unittest.TestCase):
    def test_the_lists_are_the_codes(self):
        lists = check_lists()
        self.assertEqual(lists["topology"], ["servo", "nodelets", "processes"])
        with open(os.path.join(PACKAGE, "src", "devices", "registry", "device_registry.cpp")) as f:
            backends = re.findall(r'\{"(\w+)", "\w+", (?:true|false), (?:true|false), make\w+', f.read())
        self.assertGreater(len(backends), 2)
        self.assertEqual(lists["device"], backends)
        tools = find_node("god_finger", "god_finger_experiment")
        self.assertTrue(tools, "god_finger_experiment not built")
        models = subprocess.run([tools[0], "--list-models"], check=True, capture_output=True, text=True).stdout.split()
        self.assertEqual(lists["model"], models)
        scenes = sorted(os.path.basename(p)[:-5] for p in glob.glob(os.path.join(PACKAGE, "urdf", "scenes", "*.urdf")))
        self.assertEqual(lists["scene"], scenes)
        scripts = sorted(os.path.basename(p)[:-5] for p in glob.glob(os.path.join(PACKAGE, "config", "scripts", "*.yaml")))
        self.assertEqual(lists["script"], scripts)

    def test_every_documented_command_names_real_arguments(self):
        commands = documented_commands()
        self.assertGreater(len(commands), 15, "the docs' roslaunch commands were not found")
        lists = check_lists()
        for page, launch, args in commands:
            self.assertTrue(os.path.exists(os.path.join(PACKAGE, "launch", launch)), "%s: no launch/%s" % (page, launch))
            declared = declared_args(launch)
            for name, value in args.items():
                self.assertIn(name, declared, "%s: %s has no argument '%s' (it has: %s)"
                              % (page, launch, name, ", ".join(sorted(declared))))
                if name in CHOICES:
                    self.assertIn(value, lists[name], "%s: %s:=%s is not a valid %s" % (page, name, value, name))
        print("%d documented roslaunch commands, every argument declared" % len(commands))

    def test_a_wrong_choice_stops_with_the_valid_ones(self):
        lists = check_lists()
        wrong = {"topology": "process", "device": "falcom", "scene": "table_bal", "model": "godfinger",
                 "script": "touch_spher"}
        for choice, value in wrong.items():
            result = roslaunch_nodes("demo.launch", ["%s:=%s" % (choice, value)])
            self.assertNotEqual(result.returncode, 0, "%s:=%s was accepted" % (choice, value))
            lines = [line for line in (result.stdout + result.stderr).splitlines()
                     if "%s:=%s: valid values are " % (choice, value) in line]
            self.assertEqual(len(lines), 1, result.stdout + result.stderr)
            for valid in lists[choice]:
                self.assertIn(valid, lines[0])
            print(lines[0].strip())

    def test_the_valid_choices_load(self):
        # A user's own scene bypasses the scene list; every listed value loads in demo.launch.
        for args in (["topology:=nodelets"], ["device:=omni"], ["scene:=table_torus"], ["model:=soft_finger"],
                     ["script:=press_oscillate"], ["scene_file:=/tmp/mine.urdf", "scene:=not_a_scene"]):
            result = roslaunch_nodes("demo.launch", args)
            self.assertEqual(result.returncode, 0, "%s: %s" % (args, result.stdout + result.stderr))


    def test_a_network_link_needs_processes_and_inserts_three_delay_lines(self):
        # delay:=, jitter:=, loss:= on a one-process topology stop roslaunch with one line.
        for args in (["delay:=0.03"], ["topology:=nodelets", "loss:=0.02"]):
            result = roslaunch_nodes("demo.launch", args)
            self.assertNotEqual(result.returncode, 0, "%s was accepted" % args)
            lines = [line for line in (result.stdout + result.stderr).splitlines()
                     if "a network link needs topology:=processes" in line]
            self.assertEqual(len(lines), 1, result.stdout + result.stderr)
        # With processes: the haptic node's topics go through god_finger_delay, one per topic.
        result = roslaunch_nodes("demo.launch", ["topology:=processes", "delay:=0.03"])
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        nodes = result.stdout.split()
        for link in ("/finger/link_pose", "/finger/link_feedback", "/finger/link_proxy", "/finger/link_device_energy",
                     "/finger/link_physics_energy"):
            self.assertIn(link, nodes)
        result = roslaunch_nodes("demo.launch", ["topology:=processes"])
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.assertNotIn("/finger/link_pose", result.stdout.split())


if __name__ == "__main__":
    rostest.rosrun("god_finger", "launch_arguments", LaunchArguments, sys.argv)
