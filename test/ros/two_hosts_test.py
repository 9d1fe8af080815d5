#!/usr/bin/python3
"""rostest: the haptic loop across two hosts (issue 29), as docs/devices.md's Several machines
runs it: two network namespaces joined by a veth pair (10.213.N.1 and .2), which this test makes
and tears down. Host A runs the master and the physics (physics.launch topology:=processes
scene:=table_ball); host B the device driver, the haptic node and the three god_finger_delay
links of a 30 ms round trip, without the local coupling (interface.launch device:=interactive
delay:=0.03 local_coupling:=false), its ROS_MASTER_URI host A's. On host B, link_test.py (the
link_remote.test press: the handle dragged 2 cm into the table) must pass: the links' delays on
/diagnostics, the driver's round trip over 30 ms, the table felt, and the driver's passivity
observer never below -1e-4 J with the controller acting. Needs root (ip netns); waits on
conditions with deadlines."""
import os
import signal
import subprocess
import sys
import tempfile
import time
import unittest


import rostest

HERE = os.path.dirname(os.path.abspath(__file__))
PORT = 11513


def run(*command, check=True):
    return subprocess.run(list(command), check=check, capture_output=True, text=True)


class TwoHosts(unittest.TestCase):
    def setUp(self):
        tag = os.getpid() % 10000
        self.hosts = ("gf_a_%d" % tag, "gf_b_%d" % tag)
        self.veth = ("gfa%d" % tag, "gfb%d" % tag)
        subnet = "10.213.%d" % (tag % 250)
        self.addresses = (subnet + ".1", subnet + ".2")
        self.processes = []
        self.made = False
        if os.geteuid() != 0:
            self.fail("two_hosts needs root to make network namespaces (ip netns): run scripts/test as root")
        for host in self.hosts:
            run("ip", "netns", "add", host)
        self.made = True
        run("ip", "link", "add", self.veth[0], "type", "veth", "peer", "name", self.veth[1])
        for host, veth, address in zip(self.hosts, self.veth, self.addresses):
            run("ip", "link", "set", veth, "netns", host)
            run("ip", "netns", "exec", host, "ip", "addr", "add", address + "/24", "dev", veth)
            run("ip", "netns", "exec", host, "ip", "link", "set", veth, "up")
            run("ip", "netns", "exec", host, "ip", "link", "set", "lo", "up")

    def tearDown(self):
        for process in self.processes:
            if process.poll() is None:
                os.killpg(process.pid, signal.SIGINT)
        deadline = time.time() + 15.0
        for process in self.processes:
            try:
                process.wait(timeout=max(0.1, deadline - time.time()))
            except subprocess.TimeoutExpired:
                os.killpg(process.pid, signal.SIGKILL)
                process.wait()
        if self.made:
            for host in self.hosts:
                pids = run("ip", "netns", "pids", host, check=False).stdout.split()
                for pid in pids:
                    try:
                        os.kill(int(pid), signal.SIGKILL)
                    except (ProcessLookupError, ValueError):
                        pass
                run("ip", "netns", "del", host, check=False)

    def environment(self, index):
        env = dict(os.environ)
        env["ROS_MASTER_URI"] = "http://%s:%d" % (self.addresses[0], PORT)
        env["ROS_IP"] = self.addresses[index]
        env.pop("ROS_HOSTNAME", None)
        return env

    def start(self, index, *command):
        process = subprocess.Popen(["ip", "netns", "exec", self.hosts[index], *command], env=self.environment(index),
                                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
        self.processes.append(process)
        return process

    def wait_for(self, condition, seconds, what):
        deadline = time.time() + seconds
        while time.time() < deadline:
            if condition():
                return
            time.sleep(0.2)
        self.fail("timed out after %.0f s waiting for %s" % (seconds, what))

    def test_a_press_across_two_hosts_and_a_30_ms_link_is_passive(self):
        # Host A's master, reached from host B through the veth pair (the only way between them).
        self.start(0, "roslaunch", "-p", str(PORT), "god_finger", "physics.launch", "topology:=processes",
                   "scene:=table_ball")
        master_up = lambda: run("ip", "netns", "exec", self.hosts[1], "env", "ROS_MASTER_URI=http://%s:%d" %
                                (self.addresses[0], PORT), "ROS_IP=" + self.addresses[1], "rostopic", "list",
                                check=False).returncode == 0
        self.wait_for(master_up, 60, "host A's master, seen from host B")
        self.start(1, "roslaunch", "god_finger", "interface.launch", "device:=interactive", "topology:=processes",
                   "delay:=0.03", "local_coupling:=false")
        # Its results to a file of its own (not link.test's), its output on the console (--text).
        results = os.path.join(tempfile.mkdtemp(), "two_hosts_link.xml")
        probe = subprocess.run(["ip", "netns", "exec", self.hosts[1], "/usr/bin/python3",
                                os.path.join(HERE, "link_test.py"), "--text", "--gtest_output=xml:" + results],
                               env=self.environment(1), capture_output=True, text=True, timeout=150, cwd=HERE)
        print(probe.stdout[-3000:])
        print(probe.stderr[-3000:], file=sys.stderr)
        self.assertEqual(probe.returncode, 0, "link_test.py on host B: %s" % probe.stdout[-1500:])
        self.assertIn("across a 30 ms round trip (local coupling False)", probe.stdout)


if __name__ == "__main__":
    rostest.rosrun("god_finger", "two_hosts", TwoHosts, sys.argv)
