#!/usr/bin/python3
"""rostest: in every shipped launch file, for every device, the spring the hand feels is the
one that pulls its proxy. Each launch is loaded as roslaunch would (its parameters, not its
nodes), for every device it can take; for every interface the device's profile
(config/devices/PROFILE.yaml) must sit once in the interface's namespace, which the driver,
the haptic node, the physics node and the servo node all read it from
(ros/interface_parameters.h), and no node may carry a private coupling or force limit of its
own that would override it."""
import os
import re
import subprocess
import sys
import unittest

import roslaunch.config
import rospkg
import rostest
import yaml
from roslib.packages import find_node

PACKAGE = rospkg.RosPack().get_path("god_finger")
PROFILE_KEYS = ("coupling_stiffness", "coupling_damping", "max_force")


def backend_profiles():
    """Every device backend and its profile, from the one table: deviceBackends() in
    src/devices/registry/device_registry.cpp, rows {"name", "profile", simulated, hand_target,
    factory[, renders_force]}. interface.launch must load that profile for each backend."""
    with open(os.path.join(PACKAGE, "src", "devices", "registry", "device_registry.cpp")) as f:
        source = f.read()
    rows = re.findall(r'\{"(\w+)", "(\w+)", (?:true|false), (?:true|false), make\w+(?:, (?:true|false))?\}', source)
    if len(rows) < 2:
        raise AssertionError("no backend rows found in device_registry.cpp: has the table's shape changed?")
    return dict(rows)


PROFILES = backend_profiles()


def scenarios():
    """Every scenario, from the one list (experiment.h) through god_finger_experiment, that the
    fake devices can run (`--hand fake`); each has its launch, launch/SCENARIO.launch. A scenario
    the fake hand cannot run would have none, and the tool must say so."""
    tools = find_node("god_finger", "god_finger_experiment")
    if not tools:
        raise AssertionError("god_finger_experiment not built")
    names = subprocess.run([tools[0], "--list-scenarios"], check=True, capture_output=True, text=True).stdout.split()
    launched = []
    for name in names:
        if os.path.exists(os.path.join(PACKAGE, "launch", name + ".launch")):
            launched.append(name)
            continue
        fake = subprocess.run([tools[0], "--scenario", name, "--hand", "fake", "--duration", "0.001"],
                              capture_output=True, text=True)
        if fake.returncode == 0:
            raise AssertionError("scenario %s runs with the fake hand but has no launch/%s.launch" % (name, name))
    return launched


def launches():
    """(launch file, roslaunch args) for every shipped launch and device it takes."""
    cases = []
    scenario_names = scenarios()
    for topology in ("servo", "nodelets", "processes"):
        for device in PROFILES:
            cases.append(("demo.launch", ["device:=" + device, "topology:=" + topology, "bag:=/tmp/none.bag"]))
            cases.append(("demo.launch", ["scene:=table_clutter", "device:=" + device, "topology:=" + topology,
                                          "bag:=/tmp/none.bag"]))
        for scenario in scenario_names:
            cases.append((scenario + ".launch", ["topology:=" + topology]))
        for device in ("falcon", "omni"):
            cases.append((device + ".launch", ["topology:=" + topology]))
            cases.append((device + ".launch", ["topology:=" + topology, "bimanual:=true"]))
            cases.append(("hardware.launch", ["device:=" + device, "topology:=" + topology]))
    return cases


def profile(name):
    with open(os.path.join(PACKAGE, "config", "devices", name + ".yaml")) as f:
        return yaml.safe_load(f)


class LaunchProfiles(unittest.TestCase):
    def test_every_interface_renders_the_coupling_that_pulls_its_proxy(self):
        checked = 0
        for launch, args in launches():
            path = os.path.join(PACKAGE, "launch", launch)
            config = roslaunch.config.load_config_default([(path, args)], None, verbose=False)
            params = {name: p.value for name, p in config.params.items()}
            interfaces = [name.rsplit("/", 1)[0] for name in params if name.endswith("/backend")]
            self.assertTrue(interfaces, "%s %s: no interface" % (launch, args))
            for interface in interfaces:
                backend = params[interface + "/backend"]
                expected = profile(PROFILES[backend])
                for key in PROFILE_KEYS:
                    self.assertEqual(params.get(interface + "/" + key), expected[key],
                                     "%s %s: %s/%s" % (launch, args, interface, key))
                # Issue 18: one workspace offset per device (its profile's), whichever launch
                # starts it; bimanual setups place each device on purpose.
                if not interface.endswith("/left") and not interface.endswith("/right"):
                    self.assertEqual(params.get(interface + "/workspace_offset"), expected["workspace_offset"],
                                     "%s %s: %s/workspace_offset" % (launch, args, interface))
                checked += 1
            # No node's private parameter shadows the interface's profile.
            for name in params:
                parts = name.strip("/").split("/")
                if parts[-1] in PROFILE_KEYS and "/" + "/".join(parts[:-1]) not in interfaces:
                    self.fail("%s %s: %s overrides the interface's profile" % (launch, args, name))
        print("launch profiles: %d interfaces in %d launch configurations checked" % (checked, len(launches())))


if __name__ == "__main__":
    rostest.rosrun("god_finger", "launch_profiles", LaunchProfiles, sys.argv)
