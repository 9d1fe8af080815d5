#!/usr/bin/python3
"""rostest: a recorded session replays. Runs the slide demo with the fake device, recorded
(record:=true), then the same scene with device:=replay playing that bag, recorded again, each
on a master of its own; then compares the ball's trajectories from the two bags, aligned on
the moment the ball starts to move.

Tolerance: 3 mm on the ball's position at every 50 ms over the 3 s after it starts moving,
and 0.05 rad on its final orientation. The replay reproduces the interface positions exactly;
what differs is the timing of the two runs' 1 kHz loops (which step a pose lands in) and the
60 Hz sampling of /tf, which at the ball's 5 cm/s is up to about 1 mm."""
import math
import os
import signal
import subprocess
import sys
import time
import unittest

import rosbag
import rospy
import rostest

PORT = "11533"


def run_session(arguments, log_path, seconds):
    env = dict(os.environ, ROS_MASTER_URI="http://localhost:" + PORT)
    log = open(log_path, "w")
    process = subprocess.Popen(["roslaunch", "-p", PORT, "god_finger", "demo.launch", "record:=true"] + arguments, env=env, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    time.sleep(seconds)
    os.killpg(process.pid, signal.SIGINT)
    process.wait(timeout=60)
    log.close()


def ball_track(bag_path):
    track = []
    with rosbag.Bag(bag_path) as bag:
        for _, message, _ in bag.read_messages(topics=["/tf"]):
            for transform in message.transforms:
                if transform.child_frame_id == "ball":
                    track.append((transform.header.stamp.to_sec(), transform.transform))
    return track


def onset(track):
    x0 = track[0][1].translation
    for t, transform in track:
        p = transform.translation
        if math.sqrt((p.x - x0.x) ** 2 + (p.y - x0.y) ** 2) > 0.001:
            return t
    return None


def position_at(track, t):
    for stamp, transform in track:
        if stamp >= t:
            return transform
    return track[-1][1]


class Replay(unittest.TestCase):
    def test_replayed_session_moves_the_ball_the_same_way(self):
        rospy.init_node("replay_test")
        recorded = "/tmp/god_finger_replay_recorded.bag"
        replayed = "/tmp/god_finger_replay_replayed.bag"
        for path in (recorded, replayed):
            if os.path.exists(path):
                os.remove(path)
        run_session(["script:=slide", "bag:=" + recorded], recorded + ".log", 10.0)
        self.assertTrue(os.path.exists(recorded), "the first session was not recorded")
        run_session(["device:=replay", "bag:=" + recorded, "record_bag:=" + replayed], replayed + ".log", 10.0)
        self.assertTrue(os.path.exists(replayed), "the replay was not recorded")
        a, b = ball_track(recorded), ball_track(replayed)
        self.assertGreater(len(a), 100)
        self.assertGreater(len(b), 100)
        ta, tb = onset(a), onset(b)
        self.assertIsNotNone(ta, "the ball did not move in the recorded session")
        self.assertIsNotNone(tb, "the ball did not move in the replay")
        worst = 0.0
        for k in range(61):
            pa = position_at(a, ta + 0.05 * k).translation
            pb = position_at(b, tb + 0.05 * k).translation
            worst = max(worst, math.sqrt((pa.x - pb.x) ** 2 + (pa.y - pb.y) ** 2 + (pa.z - pb.z) ** 2))
        qa, qb = a[-1][1].rotation, b[-1][1].rotation
        turn = 2.0 * math.acos(min(1.0, abs(qa.x * qb.x + qa.y * qb.y + qa.z * qb.z + qa.w * qb.w)))
        moved = math.hypot(a[-1][1].translation.x - a[0][1].translation.x, a[-1][1].translation.y - a[0][1].translation.y)
        print("replay: ball moved %.1f mm; largest position difference %.2f mm; final orientation %.4f rad apart"
              % (1e3 * moved, 1e3 * worst, turn))
        self.assertGreater(moved, 0.05)
        self.assertLess(worst, 0.003)
        self.assertLess(turn, 0.05)


if __name__ == "__main__":
    rostest.rosrun("god_finger", "replay", Replay, sys.argv)
