#!/usr/bin/python3
"""rostest: a recorded session replays exactly. Runs the slide demo with the fake device on
simulated time, recorded (record:=true sim_time:=true: the loop waits for the recorder, so the
bag holds every tick), then the same scene with device:=replay playing that bag, recorded
again, each on a master of its own; then compares the ball's poses in the two bags stamp by
stamp: on simulated time the replay puts the interface where it was at every tick, so the
ball's trajectory is the recorded one (to 1e-9 m and rad)."""
import math
import os
import signal
import subprocess
import sys
import threading
import time
import unittest

import rosbag
import rospy
import rostest

PORT = "11533"


class SimulatedClock:
    """The latest whole second of /clock on the master at `env`'s ROS_MASTER_URI, read by
    `rostopic echo` (restarted while that master is not up yet)."""

    def __init__(self, env):
        self.env = env
        self.seconds = -1
        self.process = None
        self.thread = None
        self.started = 0.0

    def poll(self):
        # At most one start a second: each is a Python process on a machine the session loads.
        if (self.process is None or self.process.poll() is not None) and time.time() - self.started > 1.0:
            if self.thread is not None:
                self.thread.join()
            self.started = time.time()
            self.process = subprocess.Popen(["rostopic", "echo", "/clock/clock/secs"], env=self.env,
                                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
                                            start_new_session=True)
            self.thread = threading.Thread(target=self.read, args=(self.process,), daemon=True)
            self.thread.start()
        return self.seconds

    def read(self, process):
        for line in process.stdout:
            if line.strip().isdigit():
                self.seconds = int(line)

    def close(self):
        if self.process is not None and self.process.poll() is None:
            os.killpg(self.process.pid, signal.SIGINT)
            self.process.wait(timeout=30)


def run_session(arguments, log_path, until, seconds):
    """Runs demo.launch with `arguments` until its simulated clock reaches `until` (s), within
    `seconds` of wall clock; returns the last clock second seen."""
    env = dict(os.environ, ROS_MASTER_URI="http://localhost:" + PORT)
    log = open(log_path, "w")
    process = subprocess.Popen(["roslaunch", "-p", PORT, "god_finger", "demo.launch", "record:=true", "sim_time:=true"]
                               + arguments, env=env, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    clock = SimulatedClock(env)
    deadline = time.time() + seconds
    while clock.poll() < until and time.time() < deadline:
        time.sleep(0.1)  # polls the clock (and restarts its reader while the master comes up)
    reached = clock.seconds
    clock.close()
    os.killpg(process.pid, signal.SIGINT)
    process.wait(timeout=60)
    log.close()
    return reached


def ball_track(bag_path):
    track = []
    with rosbag.Bag(bag_path) as bag:
        for _, message, _ in bag.read_messages(topics=["/tf"]):
            for transform in message.transforms:
                if transform.child_frame_id == "ball":
                    track.append((transform.header.stamp.to_nsec(), transform.transform))
    return track


class Replay(unittest.TestCase):
    def test_replayed_session_moves_the_ball_the_same_way(self):
        rospy.init_node("replay_test")
        recorded = "/tmp/god_finger_replay_recorded.bag"
        replayed = "/tmp/god_finger_replay_replayed.bag"
        for path in (recorded, replayed):
            if os.path.exists(path):
                os.remove(path)
        # The slide script (config/scripts/slide.yaml) runs from 2 s to 5.3 s of simulated time
        # (script_delay 2 s): each session runs until its clock reaches 8 s (the ball at rest,
        # and some 500 poses at common stamps for the comparison below).
        reached = run_session(["script:=slide", "bag:=" + recorded], recorded + ".log", 8, 45.0)
        self.assertGreaterEqual(reached, 8, "the first session's clock reached %d s of 8 within 45 s (log %s.log)"
                                % (reached, recorded))
        self.assertTrue(os.path.exists(recorded), "the first session was not recorded")
        reached = run_session(["device:=replay", "bag:=" + recorded, "record_bag:=" + replayed], replayed + ".log", 8,
                              45.0)
        self.assertGreaterEqual(reached, 8, "the replay's clock reached %d s of 8 within 45 s (log %s.log)"
                                % (reached, replayed))
        self.assertTrue(os.path.exists(replayed), "the replay was not recorded")
        a, b = dict(ball_track(recorded)), dict(ball_track(replayed))
        common = sorted(set(a) & set(b))
        self.assertGreater(len(common), 300, "too few poses at the same stamps in the two bags")
        worst = 0.0
        turn = 0.0
        for t in common:
            pa, pb = a[t].translation, b[t].translation
            worst = max(worst, math.sqrt((pa.x - pb.x) ** 2 + (pa.y - pb.y) ** 2 + (pa.z - pb.z) ** 2))
            qa, qb = a[t].rotation, b[t].rotation
            dot = min(1.0, abs(qa.x * qb.x + qa.y * qb.y + qa.z * qb.z + qa.w * qb.w))
            turn = max(turn, 2.0 * math.acos(dot) if dot < 1.0 - 1e-15 else 0.0)
        first, last = a[common[0]].translation, a[common[-1]].translation
        moved = math.hypot(last.x - first.x, last.y - first.y)
        print("replay: ball moved %.1f mm; %d poses compared, largest position difference %.3g m, "
              "orientation %.3g rad" % (1e3 * moved, len(common), worst, turn))
        self.assertGreater(moved, 0.05)
        self.assertLess(worst, 1e-9)
        self.assertLess(turn, 1e-6)


if __name__ == "__main__":
    rostest.rosrun("god_finger", "replay", Replay, sys.argv)
