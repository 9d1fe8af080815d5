#!/usr/bin/python3
"""rostest: every documented roslaunch command runs and does what it promises.

Each distinct `roslaunch god_finger FILE.launch name:=value ...` of README.md and docs/*.md
(launch_arguments_test.documented_commands) is started as written, headless (rviz:=false: the
screenshot tests look at rviz) and with a recording sent to a temporary bag, and must:
- start every finger its launch names (the servo's or the physics' `interfaces`; a hand's
  fingers under its name), each publishing its device state at a sane rate (>= 100 Hz; the
  rate itself is the bench's);
- with a scripted device (fake, fake_hand: the launches' default), touch an object: a contact
  area on /contact_areas within 30 s;
- stop cleanly on Ctrl-C (SIGINT).
Commands are run from the package's folder, as the docs type them. Commands that need what
this machine has not are skipped, and say why: a Falcon or an Omni (no device attached; their
launch stops with a clear error, node_errors_test), a replay of a bag the user recorded, a
user's own file (/abs/path/my.urdf, /tmp/mine.yaml), a pose source (pose_source_docs.test runs
its example with the docs' poses), and one half of a session across two machines
(physics.launch or interface.launch alone: loop_processes runs both)."""
import os
import signal
import subprocess
import sys
import tempfile
import time
import unittest

import rosgraph
import rospkg
import rospy
import rostest
from god_finger.msg import ContactAreaArray, DeviceState
from launch_arguments_test import documented_commands
from ros_test_support import RosTestSupport

SCRIPTED = ("fake", "fake_hand")


def why_skipped(launch, args):
    if launch in ("falcon.launch", "omni.launch", "hardware.launch"):
        return "needs a Falcon or an Omni attached"
    if launch in ("physics.launch", "interface.launch"):
        return "one half of a session across two machines (loop_processes runs both halves)"
    device = args.get("device", "fake")
    if device in ("falcon", "omni"):
        return "needs a %s attached" % device
    if device in ("omni_msgs", "ros_geomagic", "crtk", "ros_falcon"):
        return "needs the %s driver running: ros_driver_%s.test runs it against a fake of that driver" % (device, device)
    if device == "replay":
        return "replays a bag the user recorded"
    if device == "pose_source":
        return "its fingers come from a tracker's poses: pose_source_docs.test runs the docs' example with its poses"
    if any("/abs/path" in value or "my.urdf" in value or "mine.yaml" in value for value in args.values()):
        return "a user's own file"
    return None


def distinct_commands():
    seen = {}
    for page, launch, args in documented_commands():
        key = (launch, tuple(sorted(args.items())))
        seen.setdefault(key, (page, launch, args))
    return list(seen.values())


class DocsCommands(unittest.TestCase, RosTestSupport):
    def setUp(self):
        rospy.init_node("docs_commands_test")
        self.states = {}
        self.areas = 0
        self.subscribers = []

    def on_state(self, topic):
        def count(_):
            self.states[topic] = self.states.get(topic, 0) + 1
        return count

    def on_areas(self, message):
        self.areas += 1 if any(area.radius >= 0.0 for area in message.areas) else 0

    def session_nodes(self):
        """The session's nodes still registered with the master (scripts/session_check's)."""
        master = rosgraph.Master("/docs_commands_test")
        registered = set()
        for node in ("/god_finger_manager", "/servo", "/physics"):
            try:
                master.lookupNode(node)
                registered.add(node)
            except rosgraph.MasterError:
                pass
        return registered

    def interfaces(self):
        for name in ("/servo/interfaces", "/physics/interfaces"):
            if rospy.has_param(name):
                return rospy.get_param(name)
        return None

    def run_one(self, page, launch, args, bag):
        args = dict(args)
        args["rviz"] = "false"
        if "bag" in args or args.get("record") == "true":
            args["bag"] = bag
        command = ["roslaunch", "god_finger", launch] + ["%s:=%s" % item for item in sorted(args.items())]
        for subscriber in self.subscribers:
            subscriber.unregister()
        self.states = {}
        self.areas = 0
        self.subscribers = [rospy.Subscriber("/contact_areas", ContactAreaArray, self.on_areas, queue_size=10)]
        log = open(bag + ".log", "w")
        # From the package's folder, as the docs' commands are typed (relative scene files).
        # (roslaunch reads the folder from PWD, which a cwd alone does not set.)
        package = rospkg.RosPack().get_path("god_finger")
        process = subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT, start_new_session=True,
                                   cwd=package, env=dict(os.environ, PWD=package))
        try:
            self.wait_for(lambda: self.interfaces() is not None or process.poll() is not None, 60.0,
                          "%s to load its scene" % " ".join(command))
            self.assertIsNone(process.poll(), "%s (%s) exited %s" % (" ".join(command), page, process.returncode))
            interfaces = self.interfaces()

            def finger_topics():
                """The device states of the launch's fingers: NAME/device/state for a device, one
                per finger (NAME/FINGER/device/state) for a hand."""
                return sorted(t for t, _ in rospy.get_published_topics() if t.endswith("/device/state") and
                              any(t.startswith("/%s/" % name) for name in interfaces))

            self.wait_for(lambda: len(finger_topics()) >= len(interfaces), 60.0,
                          "%s: the fingers of %s" % (" ".join(command), interfaces))
            fingers = [t[1:-len("/device/state")] for t in finger_topics()]
            for finger in fingers:
                topic = "/%s/device/state" % finger
                self.subscribers.append(rospy.Subscriber(topic, DeviceState, self.on_state(topic), queue_size=2000))
            self.wait_for(lambda: len(self.states) == len(fingers), 60.0,
                          "%s: device states of all of %s" % (" ".join(command), fingers))
            before = dict(self.states)
            start = time.time()
            self.wait_for(lambda: time.time() - start >= 1.0, 2.0, "a second")
            rates = {t: (self.states[t] - before[t]) / (time.time() - start) for t in before}
            for topic, rate in rates.items():
                self.assertGreater(rate, 100.0, "%s: %s at %.0f Hz" % (" ".join(command), topic, rate))
            touched = None
            if args.get("device", "fake") in SCRIPTED:
                self.wait_for(lambda: self.areas > 0, 30.0, "%s: a scripted finger touching" % " ".join(command))
                touched = True
            print("docs_commands: %s (%s): %d finger(s) %s, lowest rate %.0f Hz%s"
                  % (" ".join(command[1:]), page, len(fingers), fingers, min(rates.values()),
                     ", touched" if touched else ""))
        finally:
            if process.poll() is None:
                os.killpg(process.pid, signal.SIGINT)
                try:
                    process.wait(timeout=30)
                except subprocess.TimeoutExpired:
                    os.killpg(process.pid, signal.SIGKILL)
                    process.wait()
            log.close()
            for name in ("/servo/interfaces", "/physics/interfaces"):
                if rospy.has_param(name):
                    rospy.delete_param(name)
            self.wait_for(lambda: not self.session_nodes(), 30.0, "the session's nodes to leave the master")
        self.assertEqual(process.returncode, 0, "%s did not stop cleanly on Ctrl-C (exit %s)"
                         % (" ".join(command), process.returncode))

    def test_every_documented_command_does_what_it_promises(self):
        folder = tempfile.mkdtemp()
        ran = 0
        for index, (page, launch, args) in enumerate(distinct_commands()):
            reason = why_skipped(launch, args)
            if reason:
                print("docs_commands: skipped %s %s (%s): %s" % (launch, args, page, reason))
                continue
            self.run_one(page, launch, args, os.path.join(folder, "session%d.bag" % index))
            ran += 1
        self.assertGreaterEqual(ran, 10, "the docs have fewer runnable commands than they had (10)")


if __name__ == "__main__":
    rostest.rosrun("god_finger", "docs_commands", DocsCommands, sys.argv)
