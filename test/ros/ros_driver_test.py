#!/usr/bin/python3
"""rostest: god_finger driven by a ROS driver a lab runs (devices/driver_bridge.h), through a fake of
that driver. usage: ros_driver_test.py DRIVER (omni_msgs | ros_geomagic | crtk | ros_falcon).

The fake is this test: it publishes exactly what the driver publishes (its topics, message types,
units and axes, at its rate), with messages genpy builds from the driver's own .msg files
(test/ros/driver_msgs/), and takes the force on the driver's force topic in the driver's type. Its
map between the driver's frame and god_finger's device frame is written here, from the drivers'
own code (docs/devices.md), not read from god_finger.

1. The reference: `roslaunch god_finger demo.launch device:=interactive`; the handle is dragged
   onto the top of the ball and held: the force the loop applies there, and where the handle is.
2. `roslaunch god_finger demo.launch device:=DRIVER`, as a user types it:
   - the stylus, above the ball, moves 1 cm to the user's right in the driver's frame: the finger
     moves 1 cm to the right in the world (-y);
   - the stylus comes down onto the ball and stays where the reference handle was: the force the
     driver gets points up in its own frame and is within 5 % of the reference's (times the ratio
     of the two profiles' coupling stiffnesses: 1 for the Touch's, 2 for the Falcon's);
   - /diagnostics reports the driver's rate (within 10 % of the fake's) and its state's age;
   - the driver falls silent: /diagnostics names its topic (ERROR), the force it last got is zero;
     with a device driver node (the topic topologies) its "DRIVER device" status is ERROR too
     (device lost); it comes back: the force comes back, and that status is no longer ERROR;
   - Ctrl-C of the launch (SIGINT): the last force the driver got is zero.
Every wait is on a condition with a deadline; the fake's timer paces the stylus."""
import math
import os
import signal
import subprocess
import sys
import threading
import time
import unittest

import genmsg
import genmsg.gentools
import genmsg.msg_loader
import genpy.dynamic
import rospkg
import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus
from geometry_msgs.msg import PoseStamped, WrenchStamped
from god_finger.msg import DeviceState
from ros_test_support import RosTestSupport, drag_marker
from sensor_msgs.msg import Joy
from visualization_msgs.msg import InteractiveMarkerFeedback

HERE = os.path.dirname(os.path.abspath(__file__))

# The real packages' md5sums, as their generated code carries them.
REAL_MD5 = {
    "omni_msgs/OmniState": "89c2a741de66e9e904f59a02b171dd6e",
    "omni_msgs/OmniFeedback": "e9083ac4fd95494e94fbb0c0f90b6c00",
    "omni_msgs/OmniButtonEvent": "fb77877e6b639935c3360838062f05f0",
    "geomagic_control/DeviceFeedback": "94755b031db27fe99c2c235c0da9b072",
    "geomagic_control/DeviceButtonEvent": "fb77877e6b639935c3360838062f05f0",
    "crtk_msgs/OperatingState": "b1bd4021639d9d9c5fbfff78d6ff3158",
    "ros_falcon/falconPos": "8219583d7802cc50be3e9ab911877ba5",
    "ros_falcon/falconForces": "8219583d7802cc50be3e9ab911877ba5",
}


def hd_from_device(d):
    """The OpenHaptics HD frame (x to the user's right, y up, z towards the user) from the device
    frame (x away from the user, y to the left, z up)."""
    return (-d[1], d[2], -d[0])


def device_from_hd(h):
    return (-h[2], -h[0], h[1])


def omni_common_from_device(d):
    """omni_common's frame: x right, y away from the user, z up (omni_state.cpp: (x, -z, y) of HD)."""
    return (-d[1], d[0], d[2])


def device_from_omni_common(o):
    return (o[1], -o[0], o[2])


# driver: namespace, its rate (Hz), m per unit, centre (driver frame and units), the frame maps,
# its "up" axis (driver frame), the force message's type and topic.
DRIVERS = {
    "omni_msgs": dict(ns="/phantom/phantom", rate=1000.0, unit=0.001, center=(0.0, 0.0, 0.0),
                      to_driver=omni_common_from_device, to_device=device_from_omni_common, up=2),
    "ros_geomagic": dict(ns="/Geomagic", rate=1000.0, unit=0.001, center=(0.0, 0.0, 0.0),
                         to_driver=hd_from_device, to_device=device_from_hd, up=1),
    "crtk": dict(ns="/arm", rate=500.0, unit=1.0, center=(0.0, 0.0, 0.0),
                 to_driver=hd_from_device, to_device=device_from_hd, up=1),
    "ros_falcon": dict(ns="/", rate=1000.0, unit=1.0, center=(0.0, 0.0, 0.11),
                       to_driver=hd_from_device, to_device=device_from_hd, up=1),
}


def load_driver_messages():
    """{type: genpy class} for every .msg of test/ros/driver_msgs, and {type: full text}."""
    context = genmsg.MsgContext.create_default()
    rospack = rospkg.RosPack()
    search = {pkg: [os.path.join(rospack.get_path(pkg), "msg")] for pkg in ("std_msgs", "geometry_msgs")}
    folders = os.path.join(HERE, "driver_msgs")
    types = []
    for pkg in sorted(os.listdir(folders)):
        folder = os.path.join(folders, pkg, "msg")
        if os.path.isdir(folder):
            search[pkg] = [folder]
            types += ["%s/%s" % (pkg, name[:-4]) for name in sorted(os.listdir(folder)) if name.endswith(".msg")]
    classes, texts, md5s = {}, {}, {}
    for name in types:
        spec = genmsg.msg_loader.load_msg_by_type(context, name, search)
        genmsg.msg_loader.load_depends(context, spec, search)
        texts[name] = genmsg.gentools.compute_full_text(context, spec)
        md5s[name] = genmsg.gentools.compute_md5(context, spec)
        classes[name] = genpy.dynamic.generate_dynamic(name, texts[name])[name]
    return classes, texts, md5s


class FakeDriver:
    """The driver: publishes the stylus at `position` (device frame, m; set by the test) in the
    driver's frame, units, types and topics at its rate; records every force it gets."""

    def __init__(self, driver, classes):
        self.name = driver
        self.spec = DRIVERS[driver]
        self.classes = classes
        self.position = (0.0, 0.0, 0.0)
        self.silent = False  # True: publishes nothing (a driver that stalled)
        self.forces = []  # (driver-frame force, its connection header)
        self.lock = threading.Lock()
        ns = self.spec["ns"].rstrip("/")
        if driver == "omni_msgs":
            self.state = rospy.Publisher(ns + "/state", classes["omni_msgs/OmniState"], queue_size=1)
            rospy.Subscriber(ns + "/force_feedback", classes["omni_msgs/OmniFeedback"], self.on_force, queue_size=100)
        elif driver == "ros_geomagic":
            self.state = rospy.Publisher(ns + "/pose", PoseStamped, queue_size=1)
            rospy.Subscriber(ns + "/force_feedback", classes["geomagic_control/DeviceFeedback"], self.on_force,
                             queue_size=100)
        elif driver == "crtk":
            self.state = rospy.Publisher(ns + "/measured_cp", PoseStamped, queue_size=1)
            self.operating = rospy.Publisher(ns + "/operating_state", classes["crtk_msgs/OperatingState"],
                                             queue_size=1, latch=True)
            operating = classes["crtk_msgs/OperatingState"]()
            operating.state, operating.is_homed = "ENABLED", True
            self.operating.publish(operating)
            self.button = rospy.Publisher(ns + "/front", Joy, queue_size=10)
            rospy.Subscriber(ns + "/servo_cf", WrenchStamped, self.on_force, queue_size=100)
        else:
            self.state = rospy.Publisher("/falconPos", classes["ros_falcon/falconPos"], queue_size=10)
            rospy.Subscriber("/falconForce", classes["ros_falcon/falconForces"], self.on_force, queue_size=100)
        self.running = True
        self.thread = threading.Thread(target=self.publish)
        self.thread.start()

    def driver_position(self):
        unit, center = self.spec["unit"], self.spec["center"]
        return [c + v / unit for v, c in zip(self.spec["to_driver"](self.position), center)]

    def message(self):
        x, y, z = self.driver_position()
        if self.name == "omni_msgs":
            state = self.classes["omni_msgs/OmniState"]()
            state.header.stamp = rospy.Time.now()
            state.pose.position.x, state.pose.position.y, state.pose.position.z = x, y, z
            state.pose.orientation.w = 1.0
            return state
        if self.name in ("ros_geomagic", "crtk"):
            pose = PoseStamped()
            pose.header.stamp = rospy.Time.now()
            pose.header.frame_id = "base" if self.name == "crtk" else ""
            pose.pose.position.x, pose.pose.position.y, pose.pose.position.z = x, y, z
            pose.pose.orientation.w = 1.0
            return pose
        position = self.classes["ros_falcon/falconPos"]()
        position.X, position.Y, position.Z = x, y, z
        return position

    def publish(self):
        period = 1.0 / self.spec["rate"]
        tick = time.time()
        while self.running and not rospy.is_shutdown():
            if not self.silent:
                self.state.publish(self.message())
            tick += period
            # Paces the driver's rate (a real driver's servo clock), not a synchronisation.
            time.sleep(max(0.0, tick - time.time()))

    def on_force(self, message):
        force = message.wrench.force if self.name == "crtk" else (
            message if self.name == "ros_falcon" else message.force)
        value = (force.X, force.Y, force.Z) if self.name == "ros_falcon" else (force.x, force.y, force.z)
        with self.lock:
            self.forces.append((value, message))

    def last_force(self):
        with self.lock:
            return self.forces[-1] if self.forces else (None, None)

    def stop(self):
        self.running = False
        self.thread.join()


def mean(values):
    return [sum(v[i] for v in values) / len(values) for i in range(3)]


class RosDriverBridge(RosTestSupport, unittest.TestCase):
    driver = "omni_msgs"
    topology = "servo"

    def setUp(self):
        rospy.init_node("ros_driver_test", anonymous=True)
        self.classes, self.texts, self.md5s = load_driver_messages()
        self.states = []
        self.pose = None
        rospy.Subscriber("/finger/device/state", DeviceState, self.states.append, queue_size=100)
        rospy.Subscriber("/finger/pose", PoseStamped, lambda m: setattr(self, "pose", m), queue_size=1)
        self.driver_status = None  # the bridge's newest status on /diagnostics
        self.device_status = None  # the device driver node's (topic topologies), named for the backend
        rospy.Subscriber("/diagnostics", DiagnosticArray, self.on_diagnostics, queue_size=20)

    def on_diagnostics(self, array):
        for status in array.status:
            if (": %s driver " % self.driver) in status.name:
                self.driver_status = status
            if status.name == "/finger/device_driver: %s device" % self.driver:
                self.device_status = status

    def driver_value(self, key):
        status = self.driver_status
        return None if status is None else next((v.value for v in status.values if v.key == key), None)

    def launch(self, device):
        command = ["roslaunch", "god_finger", "demo.launch", "device:=%s" % device, "topology:=%s" % self.topology]
        log = open("/tmp/ros_driver_test_%s_%s.log" % (self.driver, device), "w")
        process = subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
        self.addCleanup(log.close)
        self.addCleanup(lambda: process.poll() is not None or self.stop(process))  # a failed test's launch
        return process

    def stop(self, process):
        """Ctrl-C, as a user stops the launch."""
        os.killpg(process.pid, signal.SIGINT)
        try:
            process.wait(timeout=30)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
            self.fail("the launch did not stop within 30 s of Ctrl-C")
        for name in ("/servo/interfaces",):
            if rospy.has_param(name):
                rospy.delete_param(name)
        self.wait_for(lambda: not self.session_nodes(), 30.0, "the session's nodes to leave the master")

    def session_nodes(self):
        import rosnode
        return [n for n in rosnode.get_node_names() if n in ("/servo", "/god_finger_manager", "/physics") or
                n.startswith("/finger/")]

    def settled_force(self, seconds=1.0):
        """The loop's applied force (device frame) and the device's position, averaged over the
        last `seconds` of device states, once they have stopped moving."""
        def window():
            newest = self.states[-1].header.stamp.to_sec() if self.states else 0.0
            return [s for s in self.states[-3000:] if s.header.stamp.to_sec() > newest - seconds]

        def still():
            w = window()
            if len(w) < 100:
                return False
            forces = [(s.applied_force.x, s.applied_force.y, s.applied_force.z) for s in w]
            return max(f[2] for f in forces) - min(f[2] for f in forces) < 0.01
        self.wait_for(still, 30.0, "the held force to settle")
        w = window()
        return (mean([(s.applied_force.x, s.applied_force.y, s.applied_force.z) for s in w]),
                mean([(s.position.x, s.position.y, s.position.z) for s in w]))

    def test_the_driver_presses_the_ball_and_is_zeroed_on_ctrl_c(self):
        # The .msg files are the real packages': their md5sums.
        for name, md5 in self.md5s.items():
            self.assertEqual(md5, REAL_MD5[name], name)
        offset_reference = (0.0, 0.0, 0.0)  # interactive.yaml's workspace_offset (the world is its device frame)

        # 1. The reference: the interactive handle held on the top of the ball.
        reference = self.launch("interactive")
        self.wait_for(lambda: len(self.states) > 100, 60.0, "the interactive device's states")
        feedback = rospy.Publisher("/finger/device_marker/feedback", InteractiveMarkerFeedback, queue_size=50)
        self.wait_for(lambda: feedback.get_num_connections() > 0, 30.0, "the marker server")
        start = self.states[-1].position
        # 1.8 mm into the surface the proxy meets (ball 4 cm, proxy 3 mm: z 0.083): about 0.7 N, under
        # the Touch profile's continuous 0.88 N, which the force guard's budget would bring a larger
        # held force down to within seconds.
        drag_marker(feedback, start, 0.0, 0.0, 0.0812, 2.0)
        reference_force, reference_position = self.settled_force()
        reference_stiffness = rospy.get_param("/finger/coupling_stiffness")
        self.stop(reference)
        world = [p + o for p, o in zip(reference_position, offset_reference)]
        print("reference (interactive): %.4f N up at world (%.4f, %.4f, %.4f)" % (
            reference_force[2], world[0], world[1], world[2]))
        self.assertGreater(reference_force[2], 0.3, "the reference handle presses the ball")

        # 2. The driver.
        self.states[:] = []
        fake = FakeDriver(self.driver, self.classes)
        self.addCleanup(fake.stop)
        offset = (0.0, 0.0, 0.1)  # omni.yaml's and falcon.yaml's workspace_offset
        above = [w - o for w, o in zip(world, offset)]
        above[2] += 0.03
        fake.position = tuple(above)
        process = self.launch(self.driver)
        self.wait_for(lambda: self.pose is not None and len(self.states) > 100, 60.0, "the finger's pose")
        self.wait_for(lambda: rospy.get_param("/finger/workspace_offset", None) is not None, 10, "the profile")
        self.assertEqual(tuple(rospy.get_param("/finger/workspace_offset")), offset)

        # Right in the driver's frame is right in the world.
        self.wait_for(lambda: abs(self.pose.pose.position.z - (above[2] + offset[2])) < 0.002, 20,
                      "the finger at the stylus (%s)" % (above,))
        y0 = self.pose.pose.position.y
        fake.position = (above[0], above[1] - 0.01, above[2])  # 1 cm to the user's right
        self.wait_for(lambda: abs(self.pose.pose.position.y - (y0 - 0.01)) < 0.001, 10,
                      "the finger 1 cm to the right (world y %.4f -> %.4f)" % (y0, y0 - 0.01))

        # Back over the ball, then straight down onto it, held where the reference handle was.
        fake.position = tuple(above)
        self.wait_for(lambda: abs(self.pose.pose.position.y - y0) < 0.001, 10, "the finger back over the ball")
        for k in range(1, 101):
            fake.position = (above[0], above[1], above[2] - 0.03 * k / 100.0)
            time.sleep(0.02)  # paces the stylus (2 s down, as a hand moves)
        self.states[:] = []
        applied, position = self.settled_force()
        force, message = fake.last_force()
        self.assertIsNotNone(force, "the driver got no force")
        up = DRIVERS[self.driver]["up"]
        self.assertGreater(force[up], 0.3, "the force points up in the driver's frame: %s" % (force,))
        felt = DRIVERS[self.driver]["to_device"](force)
        # Held still, the force is the coupling's spring: its stiffness (the device's profile: the
        # Touch's is the interactive handle's, 400 N/m; the Falcon's 800 N/m) times the same depth.
        stiffness = rospy.get_param("/finger/coupling_stiffness")
        reference_force = [f * stiffness / reference_stiffness for f in reference_force]
        print("%s: the driver got %s N (its frame) = %s N (device frame), the reference %s N" % (
            self.driver, ["%.4f" % f for f in force], ["%.4f" % f for f in felt], ["%.4f" % f for f in reference_force]))
        self.assertLess(abs(felt[2] - reference_force[2]), 0.05 * reference_force[2],
                        "held at the reference's place, the force is within 5 %% of it: %.4f N vs %.4f N" % (
                            felt[2], reference_force[2]))
        self.assertLess(math.hypot(felt[0], felt[1]), 0.1 * reference_force[2], felt)
        # What god_finger sends is the driver's own message: type, md5sum, definition.
        header = message._connection_header
        if self.driver != "crtk":
            self.assertEqual(self.texts[header["type"]], header["message_definition"], header["type"])
            self.assertEqual(REAL_MD5[header["type"]], header["md5sum"])

        # Measured: the driver's rate and its state's age.
        self.wait_for(lambda: self.driver_status is not None and self.driver_status.level == DiagnosticStatus.OK, 10,
                      "the driver's status on /diagnostics")
        rate = float(self.driver_value("driver_rate_hz"))
        print("%s: /diagnostics %s: %s, driver_rate_hz %.0f, state_age_ms %s" % (
            self.driver, self.driver_status.name, self.driver_status.message, rate, self.driver_value("state_age_ms")))
        self.assertLess(abs(rate - DRIVERS[self.driver]["rate"]), 0.1 * DRIVERS[self.driver]["rate"])
        self.assertLess(float(self.driver_value("state_age_ms")), 500.0)

        # The driver falls silent: a device fault that names its topic, and a zero force.
        fake.silent = True
        self.wait_for(lambda: self.driver_status.level == DiagnosticStatus.ERROR, 10, "the stale driver's ERROR")
        topic = {"omni_msgs": "/phantom/phantom/state", "ros_geomagic": "/Geomagic/pose", "crtk": "/arm/measured_cp",
                 "ros_falcon": "/falconPos"}[self.driver]
        self.assertIn("no state on " + topic, self.driver_status.message)
        self.wait_for(lambda: fake.last_force()[0] == (0.0, 0.0, 0.0), 5, "a zero force for a stale driver")
        if self.topology != "servo":
            self.wait_for(lambda: self.device_status is not None and self.device_status.level == DiagnosticStatus.ERROR,
                          10, "the device driver's status ERROR while its driver is stale")
            print("%s: /diagnostics %s: %s" % (self.driver, self.device_status.name, self.device_status.message))
            self.assertIn("device lost", self.device_status.message)
        fake.silent = False
        self.wait_for(lambda: (fake.last_force()[0] or (0, 0, 0))[up] > 0.3, 10, "the force back with the driver")
        if self.topology != "servo":
            self.wait_for(lambda: "device lost" not in self.device_status.message, 10,
                          "the device driver's status without its loss once the driver is back")

        # Ctrl-C: the last force the driver got is zero.
        self.stop(process)
        last, _ = fake.last_force()
        print("%s: after Ctrl-C the last force was %s (%d forces received)" % (self.driver, last, len(fake.forces)))
        self.assertEqual(last, (0.0, 0.0, 0.0))


if __name__ == "__main__":
    words = [a for a in sys.argv[1:] if not a.startswith("--") and ":=" not in a]
    RosDriverBridge.driver = words[0] if words else "omni_msgs"
    RosDriverBridge.topology = words[1] if len(words) > 1 else "servo"
    rostest.rosrun("god_finger", "ros_driver_" + RosDriverBridge.driver, RosDriverBridge, sys.argv)
