#!/usr/bin/python3
"""rostest: a haptic loop across a delayed network (demo.launch topology:=processes delay:=0.03
device:=interactive). Three god_finger_delay links carry the finger's pose, feedback and proxy
15 ms each way, and say so on /diagnostics; the device driver's round trip (a device state to
the command that answers it) is at least the added 30 ms; the user drags the handle 2 cm into
the table (the scene's stiff wall) and holds it: the hand feels the table, and the driver's
passivity observer (haptics/passivity_controller.h) finds the loop passive: the energy the hand
put in never went below -1e-4 J, with the controller on (the default): with the local coupling
(link.test: the spring rendered at the device against a god-object on the last step's contact
planes, runtime/multirate_render.h, so free motion is free and a wall not yet touched comes a
round trip late) and
without it (link_remote.test: the physics' force a round trip late, where the controller has to
act).
Waits on conditions with deadlines."""
import math
import sys
import unittest

import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus
from geometry_msgs.msg import Point, WrenchStamped
from god_finger.msg import DeviceState, PortEnergy
from ros_test_support import RosTestSupport, drag_marker
from visualization_msgs.msg import InteractiveMarkerFeedback

LINKS = ("/finger/link/interface_pose", "/finger/feedback", "/finger/proxy_state")


class Link(RosTestSupport, unittest.TestCase):
    def setUp(self):
        rospy.init_node("link_test")
        self.statuses = {}  # status name -> {key: value}, the newest
        self.reports = {}  # status name -> how many came
        self.stamps = {}  # status name -> the newest one's stamp (s, ROS clock)
        self.levels = {}  # status name -> the newest one's (level, message)
        self.state = None
        self.force = 0.0
        self.applied = 0.0  # N: the largest force the device applied since it was last cleared
        rospy.Subscriber("/diagnostics", DiagnosticArray, self.on_diagnostics, queue_size=20)
        rospy.Subscriber("/finger/device/state", DeviceState, self.on_state, queue_size=10)
        rospy.Subscriber("/finger/link/feedback", WrenchStamped, self.on_feedback, queue_size=10)

    def on_diagnostics(self, array):
        for status in array.status:
            self.statuses[status.name] = {pair.key: pair.value for pair in status.values}
            self.reports[status.name] = self.reports.get(status.name, 0) + 1
            self.stamps[status.name] = array.header.stamp.to_sec()
            self.levels[status.name] = (status.level, status.message)

    def on_state(self, message):
        self.state = message.position
        f = message.applied_force
        self.applied = max(self.applied, math.sqrt(f.x * f.x + f.y * f.y + f.z * f.z))

    def on_feedback(self, message):
        f = message.wrench.force
        self.force = math.sqrt(f.x * f.x + f.y * f.y + f.z * f.z)

    def status(self, start):
        """The newest status whose name starts with `start`, or None."""
        for name, values in list(self.statuses.items()):
            if name.startswith(start):
                return values
        return None

    def driver(self):
        for name, values in list(self.statuses.items()):
            if name.startswith("/finger/device_driver") and "passivity_lowest_energy_J" in values:
                return values
        return None

    def test_a_press_across_the_link_is_felt_and_passive(self):
        for link in LINKS:
            self.wait_for(lambda: self.status("delay: " + link) is not None, 30, "the link %s on /diagnostics" % link)
        drag = rospy.Publisher("/finger/device_marker/feedback", InteractiveMarkerFeedback, queue_size=10)
        self.wait_for(lambda: self.state is not None and drag.get_num_connections() > 0, 30,
                      "the handle's device state and its marker server")
        # Beside the ball (4 cm radius at the origin), then 2 cm into the table (its top z = 0; the
        # interactive profile's workspace is the world's).
        self.applied = 0.0
        drag_marker(drag, self.state, 0.1, 0.0, 0.05, 1.0)
        # The hand arrives beside the ball before it presses: the handle there and the coupling
        # relaxed (on a loaded machine the drag's last events come late; pressing out of a motion
        # still under way, a 15 ms-late god-object gave the hand up to 0.015 J: issue 29's note).
        self.wait_for(lambda: self.state is not None and
                      math.dist((self.state.x, self.state.y, self.state.z), (0.1, 0.0, 0.05)) < 1e-3 and
                      self.force < 0.05, 10, lambda: "the handle beside the ball, at rest (%s, %.3f N)" %
                      (self.state, self.force))
        # Free motion through the link: with the local coupling the hand feels nothing (a god-object
        # that came 15 ms late, fixed, dragged it back by the coupling's stiffness times its move:
        # 2.77 N here, measured in stop 44); forwarded, the physics' proxy's own lag, late.
        free_motion = self.applied
        print("free motion across the link (local coupling %s): largest force on the hand %.3f N" %
              (rospy.get_param("/finger/haptic/local_coupling", True), free_motion))
        if rospy.get_param("/finger/haptic/local_coupling", True):
            self.assertLess(free_motion, 0.05)
        # What the free motion moved through the channel. The physics port counts the force the
        # last step holds for the hand's position (runtime/multirate_render.h heldForce: what the
        # local coupling renders): none in free space, so free motion moves nothing through it
        # (until stop 49 it counted the world's coupling pulling its proxy after the hand: a tenth
        # of a joule out that no one paid for).
        device_free = self.newer("/finger/haptic: haptic")[1]
        physics_free = self.newer("/physics: channel finger")[1]
        print("channel after the free motion: device port in %s J out %s J; physics port in %s J out %s J" %
              (device_free.get("channel_energy_in_J"), device_free.get("channel_energy_out_J"),
               physics_free.get("channel_energy_in_J"), physics_free.get("channel_energy_out_J")))
        self.assertEqual(float(physics_free["channel_energy_out_J"]), 0.0)
        drag_marker(drag, Point(0.1, 0.0, 0.05), 0.1, 0.0, -0.02, 1.0)
        self.wait_for(lambda: self.force > 1.0, 20, lambda: "the hand to feel the table (%.2f N)" % self.force)
        # Each link delays by 15 ms (its mean over the last second).
        for link in LINKS:
            self.wait_for(lambda: float(self.status("delay: " + link).get("mean delay (s), last second", "nan")) > 0.014,
                          10,
                          lambda: "link %s's delay (%s)" % (link, self.status("delay: " + link)))
        # The driver's round trip (a device state to the force that answers it): with the local
        # coupling (the default) the haptic node answers at once, the spring against a god-object
        # that comes 15 ms late; without it the answer is the physics', through both ways.
        local = rospy.get_param("/finger/haptic/local_coupling", True)
        if local:
            self.wait_for(lambda: self.driver() is not None and float(self.driver()["round_trip_us_p50"]) < 15000.0, 10,
                          "the driver's round trip under one way's delay (the local coupling)")
        else:
            self.wait_for(lambda: self.driver() is not None and float(self.driver()["round_trip_us_p50"]) >= 30000.0, 10,
                          "the driver's round trip over the link's 30 ms")
        # Held there for 2 s (pressing the table), the loop through the link stays passive.
        held = rospy.get_time() + 2.0
        self.wait_for(lambda: rospy.get_time() > held and self.force > 1.0 and
                      float(self.driver()["passivity_energy_J"]) != 0.0, 10, "2 s of pressing")
        driver = self.driver()
        lowest = float(driver["passivity_lowest_energy_J"])
        print("across a 30 ms round trip (local coupling %s): %.2f N on the hand; driver round trip p50 %.1f ms; "
              "passivity: energy %s J, lowest %s J, damping took %s J at %s ticks" %
              (local, self.force, 1e-3 * float(driver["round_trip_us_p50"]), driver["passivity_energy_J"], lowest,
               driver["passivity_dissipated_J"], driver["passivity_damped_ticks"]))
        # Passive either way, with the controller on (the default); without the local coupling
        # the physics' force comes a round trip late, and the controller has to act.
        self.assertGreaterEqual(lowest, -1e-4)
        limit = float(driver["passivity_damping_limit"])  # the profile's, or the code's default
        self.assertEqual(limit, rospy.get_param("/finger/passivity_damping_limit", limit))
        self.assertGreater(limit, 0.0)
        if not local:
            self.assertGreater(float(driver["passivity_dissipated_J"]), 0.0)
        self.check_channel()

    def newer(self, name, after=None):
        """The next report of status `name` after this call (and stamped after `after`, s):
        (stamp, values)."""
        seen = self.reports.get(name, 0)
        self.wait_for(lambda: self.reports.get(name, 0) > seen and (after is None or self.stamps[name] > after), 10,
                      "a new report of %s" % name)
        return self.stamps[name], self.statuses[name]

    def check_figure_received(self, sender, receiver):
        """The receiver's figure of the sender's E_in lies between the sender's own in a report
        made well before (0.1 s: more than the 15 ms the packets travel) and in one made after."""
        before_stamp, before = self.newer(sender)
        received_stamp, received = self.newer(receiver, before_stamp + 0.1)
        _, after = self.newer(sender, received_stamp + 0.01)
        figure = float(received["channel_remote_energy_in_J"])
        print("channel: %s received %.6g J of %s's E_in, which counted %s J before and %s J after" %
              (receiver, figure, sender, before["channel_energy_in_J"], after["channel_energy_in_J"]))
        self.assertGreaterEqual(figure, float(before["channel_energy_in_J"]))
        self.assertLessEqual(figure, float(after["channel_energy_in_J"]))

    def check_channel(self):
        """The channel's two ports (src/ros/channel_port.h): each counts its own energy and
        receives the other's E_in through the link, 15 ms late, never more than the sender has."""
        device_name = "/finger/haptic: haptic"
        physics_name = "/physics: channel finger"
        for name in (device_name, physics_name):
            self.wait_for(lambda: name in self.statuses, 10, "%s on /diagnostics" % name)
        device = self.statuses[device_name]
        physics = self.statuses[physics_name]
        print("channel: device port %s" % {k: v for k, v in device.items() if k.startswith("channel")})
        print("channel: physics port %s" % {k: v for k, v in physics.items() if k.startswith("channel")})
        for values in (device, physics):
            self.assertGreater(int(values["channel_packets"]), 1000)  # ~1 kHz each way for seconds
            self.assertEqual(values["channel_rejected_packets"], "0")
        # The hand pressed 2 cm into the table through the channel: its work, into the channel.
        self.assertGreater(float(device["channel_energy_in_J"]), 0.01)
        # The physics port's controller (on by default, the device profile's passivity_*): its
        # margin never below the contact's credit (passivity_contact_credit, 1e-4 J), however late
        # the device's energy comes; with the local coupling the hand's push is paid a round trip
        # after the table's first force, so the controller acts (holds the world's target back).
        self.assertGreaterEqual(float(physics["channel_lowest_margin_J"]), -1e-4 - 1e-9)
        if rospy.get_param("/finger/haptic/local_coupling", True):
            self.assertGreater(int(physics["channel_controlled_steps"]), 0)
        # Each port's status level follows its margin (runtime/diagnostic_levels.h): below minus the
        # contact's credit (passivity_contact_credit, 1e-4 J) at least WARN, naming the margin; at
        # or above it, no word of it.
        for name in (device_name, physics_name):
            _, values = self.newer(name)
            level, message = self.levels[name]
            margin = float(values["channel_margin_J"])
            print("channel: %s margin %.6g J, level %d, %r" % (name, margin, level, message))
            if margin < -1e-4:
                self.assertGreaterEqual(level, DiagnosticStatus.WARN, message)
                self.assertIn("energy margin", message)
            else:
                self.assertNotIn("energy margin", message)
        # Each side's figure of the other's E_in: what the other had counted by then, across the
        # link, never more.
        self.check_figure_received(physics_name, device_name)
        self.check_figure_received(device_name, physics_name)
        # A malformed packet (a NaN, a negative energy) into either side is refused and counted; the
        # figure it would have replaced stays.
        bad = {device_name: ("/finger/link/physics_energy", float("nan")),
               physics_name: ("/finger/device_energy", -1.0)}
        for name, (topic, energy) in bad.items():
            publisher = rospy.Publisher(topic, PortEnergy, queue_size=10)
            self.wait_for(lambda: publisher.get_num_connections() > 0, 10, "a subscriber of %s" % topic)
            packet = PortEnergy()
            packet.header.stamp = rospy.Time.now()
            packet.energy_in = energy
            packet.session = rospy.Time(1.0)
            _, before = self.newer(name)
            publisher.publish(packet)
            self.wait_for(lambda: self.statuses[name]["channel_rejected_packets"] == "1", 10,
                          lambda: "%s to count the packet (%s)" % (name, self.statuses[name]))
            self.assertGreaterEqual(float(self.statuses[name]["channel_remote_energy_in_J"]),
                                    float(before["channel_remote_energy_in_J"]))

if __name__ == "__main__":
    rostest.rosrun("god_finger", "link", Link, sys.argv)
