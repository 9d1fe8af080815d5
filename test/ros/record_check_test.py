#!/usr/bin/python3
"""rostest (record_check.test): a recording that cannot start is refused before the session
starts, with one line naming the bag's path (launch/record.launch runs scripts/record_check while
roslaunch reads the files). The check alone: a missing folder, a folder that is a file, a path
that is a folder and an empty path are refused with one line naming the path; a writable folder
is taken (the bag's full path printed, ".bag" added as rosbag adds it), a relative path in
$ROS_HOME, where roslaunch runs the recorder. Then the demo with record:=true and a bag in a
missing folder exits non-zero with exactly one line naming the path, before any node starts."""
import os
import signal
import subprocess
import sys
import tempfile
import unittest

import rospkg
import rostest

CHECK = os.path.join(rospkg.RosPack().get_path("god_finger"), "scripts", "record_check")


def run(command, env=None, timeout=60):
    """`command`'s exit status and output (stdout and stderr), its process group stopped if it
    outlives `timeout` (a launch that was not refused)."""
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True,
                               env=env, start_new_session=True)
    try:
        output, _ = process.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGINT)
        output, _ = process.communicate(timeout=30)
        return None, output
    return process.returncode, output


class RecordCheck(unittest.TestCase):
    def refused(self, bag, why, env=None):
        code, output = run([CHECK, bag] if bag is not None else [CHECK], env=env)
        lines = output.splitlines()
        self.assertEqual(code, 1, output)
        self.assertEqual(len(lines), 1, output)
        self.assertIn(why, lines[0])
        return lines[0]

    def test_the_check_names_the_path_and_why(self):
        folder = tempfile.mkdtemp()
        a_file = os.path.join(folder, "a_file")
        open(a_file, "w").close()
        print(self.refused("/no/such/dir/x.bag", "/no/such/dir/x.bag: its folder /no/such/dir does not exist"))
        self.refused(os.path.join(a_file, "x.bag"), "%s is not a folder" % a_file)
        os.makedirs(os.path.join(folder, "session.bag"))
        self.refused(os.path.join(folder, "session.bag"), "it is a folder")
        self.refused("", "the bag's path is empty")
        self.refused(None, "the bag's path is empty")  # an empty $(arg bag) gives no argument
        code, output = run([CHECK, os.path.join(folder, "take")])
        self.assertEqual((code, output.strip()), (0, os.path.join(folder, "take.bag")))
        environment = dict(os.environ, ROS_HOME=folder)
        code, output = run([CHECK, "relative.bag"], env=environment)
        self.assertEqual((code, output.strip()), (0, os.path.join(folder, "relative.bag")))
        self.refused("missing/relative.bag", os.path.join(folder, "missing") + " does not exist", env=environment)

    def test_the_demo_is_refused_before_it_starts_a_node(self):
        bag = "/no/such/dir/x.bag"
        command = ["roslaunch", "god_finger", "demo.launch", "record:=true", "record_bag:=" + bag]
        code, output = run(command, timeout=60)
        print("%s: exit %s" % (" ".join(command), code))
        self.assertIsNotNone(code, "the demo ran with a bag it cannot write:\n" + output)
        self.assertNotEqual(code, 0, output)
        naming = [line for line in output.splitlines() if "cannot record to " + bag in line]
        self.assertEqual(len(naming), 1, "no one-line refusal naming %s in:\n%s" % (bag, output))
        print("refused: " + naming[0])
        self.assertNotIn("process[", output, "a node started before the refusal:\n" + output)


if __name__ == "__main__":
    rostest.rosrun("god_finger", "record_check", RecordCheck, sys.argv)
