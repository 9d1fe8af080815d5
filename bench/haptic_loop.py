#!/usr/bin/python3
"""Haptic loop, speed against error: nodelets or separate processes x forwarded or local coupling.

usage: bench/haptic_loop.py OUT.jsonl [--seconds S]   (needs a sourced god_finger workspace)

For each of the four set-ups it runs demo.launch headless with the fake device on the script
press_oscillate (press the ball's top, oscillate the press at 2 Hz, then hold still), records
a bag, and measures:
- rendered stiffness error: the force the device applied (DeviceState.applied_force) against the
  handle's depth into the ball (from the interface pose of the same device state, ball radius
  + proxy radius - distance to the ball's centre), fitted |F| = k_rendered * depth + b over
  each 0.5 s oscillation cycle; error = |k_rendered - k| / k with k the profile's 400 N/m
  (median and worst cycle); plus the RMS of |F| - k * depth (N, median cycle), which a late
  force inflates;
- force jitter: while holding still, the standard deviation of |F| in 100 ms windows (median
  and worst window, N);
- CPU: user + system time of the launched god_finger processes (not the recorder, not the
  master) over the run, as a share of one core;
- the loop's round trip p50 / p99 from the driver's diagnostics;
- resident memory (VmRSS, MB): the physics node (processes) or the nodelet manager holding
  all three nodes (nodelets), on the demo scene.
Prints one JSON line per set-up to OUT.jsonl.
"""
import json
import math
import os
import signal
import subprocess
import sys
import tempfile
import time

import rosbag

BALL_CENTRE_Z = 0.04  # m, table_sphere: ball of radius 4 cm resting on the table
SURFACE = 0.04 + 0.003  # ball radius + proxy radius (m)
STIFFNESS = 400.0  # N/m, config/devices/fake.yaml
TICKS = os.sysconf("SC_CLK_TCK")


def descendants(root):
    children = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/stat") as stat:
                    fields = stat.read().rsplit(")", 1)[1].split()
                children.setdefault(int(fields[1]), []).append(int(entry))
            except OSError:
                continue
    found, stack = [], [root]
    while stack:
        pid = stack.pop()
        for child in children.get(pid, []):
            found.append(child)
            stack.append(child)
    return found


def cpu_seconds(pids):
    total = 0.0
    for pid in pids:
        try:
            with open(f"/proc/{pid}/cmdline") as cmdline:
                command = cmdline.read()
            if "record" in command or "rosmaster" in command or "rosout" in command:
                continue
            with open(f"/proc/{pid}/stat") as stat:
                fields = stat.read().rsplit(")", 1)[1].split()
            total += (int(fields[11]) + int(fields[12])) / TICKS
        except OSError:
            continue
    return total


def resident_mb(pids, needle):
    total = 0.0
    for pid in pids:
        try:
            with open(f"/proc/{pid}/cmdline") as cmdline:
                if needle not in cmdline.read():
                    continue
            with open(f"/proc/{pid}/status") as status:
                for line in status:
                    if line.startswith("VmRSS:"):
                        total += int(line.split()[1]) / 1024.0
        except OSError:
            continue
    return total


def median(values):
    ordered = sorted(values)
    return ordered[len(ordered) // 2]


def analyse(bag_path):
    states, poses = {}, {}
    trips50, trips99 = [], []
    with rosbag.Bag(bag_path) as bag:
        for topic, message, _ in bag.read_messages(topics=["/finger/device/state", "/finger/pose", "/diagnostics"]):
            if topic == "/finger/device/state":
                f = message.applied_force
                states[message.header.stamp.to_nsec()] = math.sqrt(f.x * f.x + f.y * f.y + f.z * f.z)
            elif topic == "/finger/pose":
                p = message.pose.position
                poses[message.header.stamp.to_nsec()] = math.sqrt(p.x * p.x + p.y * p.y + (p.z - BALL_CENTRE_Z) ** 2)
            else:
                for status in message.status:
                    values = {pair.key: pair.value for pair in status.values}
                    if values.get("round_trip_us_p50", "null") != "null":
                        trips50.append(float(values["round_trip_us_p50"]))
                        trips99.append(float(values["round_trip_us_p99"]))
    stamps = sorted(s for s in states if s in poses)
    if len(stamps) < 1000:
        raise RuntimeError(f"{bag_path}: only {len(stamps)} device states with a pose")
    t0 = stamps[0]
    # The script starts ~2 s (script_delay) after the launch: find the first touch.
    touch = next((s for s in stamps if states[s] > 0.5), None)
    if touch is None:
        raise RuntimeError(f"{bag_path}: the finger never touched the ball")
    # Oscillating: ten 0.5 s windows (one 2 Hz cycle each), a fit per window; medians over
    # windows, so that one scheduling hiccup on a loaded machine shows in the worst window,
    # not in the typical value.
    slopes, rms = [], []
    for w in range(10):
        window = [s for s in stamps if touch + (0.5 + 0.5 * w) * 1e9 <= s < touch + (1.0 + 0.5 * w) * 1e9]
        if len(window) < 100:
            continue
        depth = [SURFACE - poses[s] for s in window]
        force = [states[s] for s in window]
        n = len(depth)
        mean_d, mean_f = sum(depth) / n, sum(force) / n
        sxx = sum((d - mean_d) ** 2 for d in depth)
        sxy = sum((d - mean_d) * (f - mean_f) for d, f in zip(depth, force))
        slopes.append(sxy / sxx if sxx > 0 else float("nan"))
        rms.append(math.sqrt(sum((f - STIFFNESS * d) ** 2 for d, f in zip(depth, force)) / n))
    # Holding still: 100 ms windows, the force's standard deviation about each window's mean.
    jitters = []
    for w in range(18):
        window = [states[s] for s in stamps if touch + (7.0 + 0.1 * w) * 1e9 <= s < touch + (7.1 + 0.1 * w) * 1e9]
        if len(window) < 50:
            continue
        mean = sum(window) / len(window)
        jitters.append(math.sqrt(sum((f - mean) ** 2 for f in window) / len(window)))
    hold = [states[s] for s in stamps if touch + 7.0e9 <= s <= touch + 8.8e9]
    if not slopes or not jitters:
        raise RuntimeError(f"{bag_path}: too few samples in the oscillation or the hold")
    errors = [abs(k - STIFFNESS) / STIFFNESS for k in slopes]
    trips50.sort()
    trips99.sort()
    return {
        "windows": len(slopes),
        "k_rendered": median(slopes),
        "stiffness_error": median(errors),
        "stiffness_error_worst": max(errors),
        "force_rms_error_N": median(rms),
        "hold_force_N": sum(hold) / max(len(hold), 1),
        "jitter_N": median(jitters),
        "jitter_worst_N": max(jitters),
        "round_trip_p50_us": trips50[len(trips50) // 2] if trips50 else None,
        "round_trip_p99_us": trips99[len(trips99) // 2] if trips99 else None,
        "first_touch_s": (touch - t0) / 1e9,
    }


def run(standalone, local, seconds, directory):
    name = ("processes" if standalone else "nodelets") + "/" + ("local" if local else "forwarded")
    bag = os.path.join(directory, name.replace("/", "_") + ".bag")
    command = ["roslaunch", "god_finger", "demo.launch", "script:=press_oscillate",
               f"standalone:={'true' if standalone else 'false'}", f"local_coupling:={'true' if local else 'false'}"]
    launch = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    # Only what is analysed is recorded (a full recording loads the 2 cores and the round trip).
    recorder = subprocess.Popen(["rosbag", "record", "-O", bag, "/finger/device/state", "/finger/pose", "/diagnostics",
                                 "__name:=bench_recorder"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                start_new_session=True)
    time.sleep(3.0)  # nodes up, script not yet started (script_delay 2 s after the launch's epoch)
    cpu_start, wall_start = cpu_seconds(descendants(launch.pid)), time.monotonic()
    time.sleep(seconds)
    pids = descendants(launch.pid)
    cpu_end, wall_end = cpu_seconds(pids), time.monotonic()
    # Resident size: the physics node (standalone) or the manager holding all three nodelets.
    resident = resident_mb(pids, "physics_node") if standalone else resident_mb(pids, "manager")
    for process in (recorder, launch):
        os.killpg(process.pid, signal.SIGINT)
        try:
            process.wait(timeout=30)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
    result = {"setup": name, "cpu_cores": (cpu_end - cpu_start) / (wall_end - wall_start), "resident_mb": resident}
    result.update(analyse(bag))
    return result


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    seconds = float(sys.argv[3]) if len(sys.argv) > 3 and sys.argv[2] == "--seconds" else 11.0
    master = subprocess.Popen(["roscore", "-p", "11411"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                              start_new_session=True)
    os.environ["ROS_MASTER_URI"] = "http://localhost:11411"
    time.sleep(3.0)
    try:
        with tempfile.TemporaryDirectory() as directory, open(sys.argv[1], "w") as out:
            for standalone in (False, True):
                for local in (False, True):
                    result = run(standalone, local, seconds, directory)
                    print(json.dumps(result), flush=True)
                    out.write(json.dumps(result) + "\n")
    finally:
        os.killpg(master.pid, signal.SIGINT)
        master.wait(timeout=30)
    return 0


if __name__ == "__main__":
    sys.exit(main())
