#!/usr/bin/python3
"""Haptic loop, timing and speed against error, in every topology, idle and loaded.

usage: bench/haptic_loop.py OUT.jsonl [--seconds S]   (needs a sourced god_finger workspace)

Set-ups: the servo loop (topology servo); driver, haptic and physics as nodelets or as
processes, each with the physics' feedback forwarded or the coupling rendered locally. Each
runs twice: idle (only the analysed topics recorded), and under the standard background load:
one busy process per core at normal priority, the full recording (record:=true) and rviz under
Xvfb (software GL). Each run is demo.launch with the fake device on the script press_oscillate
(press the ball's top, oscillate the press at 2 Hz, then hold still) for S seconds (60), and
measures:
- the loop's rate over the run (device states over the span of their stamps), its period
  (successive device-state stamps: the servo stamps a state when its device was read, the
  driver when it publishes it from its loop) and device-to-force latency (the servo's read to
  force command per tick, ~timing_csv; the driver's round trip state -> force command per
  command), as p50 / p99 / max, with histograms kept for the plots;
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

BALL_CENTRE_Z = 0.04  # m, the demo's table_ball (table_sphere's geometry): ball of radius 4 cm on the table
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
    with rosbag.Bag(bag_path) as bag:
        for topic, message, _ in bag.read_messages(topics=["/finger/device/state", "/finger/pose"]):
            if topic == "/finger/device/state":
                f = message.applied_force
                states[message.header.stamp.to_nsec()] = math.sqrt(f.x * f.x + f.y * f.y + f.z * f.z)
            elif topic == "/finger/pose":
                p = message.pose.position
                poses[message.header.stamp.to_nsec()] = math.sqrt(p.x * p.x + p.y * p.y + (p.z - BALL_CENTRE_Z) ** 2)
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
    return {
        "windows": len(slopes),
        "k_rendered": median(slopes),
        "stiffness_error": median(errors),
        "stiffness_error_worst": max(errors),
        "force_rms_error_N": median(rms),
        "hold_force_N": sum(hold) / max(len(hold), 1),
        "jitter_N": median(jitters),
        "jitter_worst_N": max(jitters),
        "first_touch_s": (touch - t0) / 1e9,
    }


# servo/clutter: the servo loop on the heavy scene (table_clutter, 108 bodies), the fake device
# pressing and dragging the pile's top box (script touch_clutter): timing only (the stiffness and
# jitter analysis is the ball's).
HEAVY = "servo/clutter"
SETUPS = [
    ("servo", ["topology:=servo"]),
    (HEAVY, ["topology:=servo", "scene:=table_clutter"]),
    ("nodelets/forwarded", ["topology:=nodelets", "local_coupling:=false"]),
    ("nodelets/local", ["topology:=nodelets", "local_coupling:=true"]),
    ("processes/forwarded", ["topology:=processes", "local_coupling:=false"]),
    ("processes/local", ["topology:=processes", "local_coupling:=true"]),
]


def percentiles(values):
    ordered = sorted(values)
    if not ordered:
        return {"p50": None, "p99": None, "max": None}
    return {"p50": ordered[len(ordered) // 2], "p99": ordered[min(len(ordered) - 1, int(0.99 * len(ordered)))],
            "max": ordered[-1]}


def timing(bag_path, latency_csv, start_ns, end_ns):
    stamps = []
    with rosbag.Bag(bag_path) as bag:
        for _, message, _ in bag.read_messages(topics=["/finger/device/state"]):
            stamp = message.header.stamp.to_nsec()
            if start_ns <= stamp <= end_ns:
                stamps.append(stamp)
    stamps.sort()
    periods = [(b - a) / 1e3 for a, b in zip(stamps, stamps[1:])]
    rate = (len(stamps) - 1) / ((stamps[-1] - stamps[0]) / 1e9) if len(stamps) > 1 else 0.0
    latencies = []
    with open(latency_csv) as handle:
        next(handle)
        column = 1 if latency_csv.endswith("servo.csv") else 0
        for line in handle:
            latencies.append(float(line.split(",")[column]))
    return {"rate_hz": rate, "ticks": len(stamps), "period_us": percentiles(periods),
            "latency_us": percentiles(latencies), "period_hist": histogram(periods), "latency_hist": histogram(latencies)}


def histogram(values, bins=200, top=4000.0):
    """Counts of values (us) in 20 us bins up to 4 ms, plus one overflow bin."""
    counts = [0] * (bins + 1)
    for value in values:
        counts[min(bins, int(value / (top / bins)))] += 1
    return counts


def busy_loops():
    return [subprocess.Popen(["sh", "-c", "while :; do :; done"], start_new_session=True)
            for _ in range(os.cpu_count() or 2)]


def run(name, arguments, loaded, seconds, directory):
    label = name + (" loaded" if loaded else " idle")
    stem = os.path.join(directory, label.replace("/", "_").replace(" ", "_"))
    bag = stem + ".bag"
    servo = name.startswith("servo")
    latency_csv = stem + ("_servo.csv" if servo else "_driver.csv")
    subprocess.run(["rosparam", "set", "/servo/timing_csv" if servo else "/finger/device_driver/timing_csv",
                    latency_csv], check=True)
    script = "touch_clutter" if name == HEAVY else "press_oscillate"
    command = ["roslaunch", "god_finger", "demo.launch", "script:=" + script] + arguments
    env = dict(os.environ)
    extra = []
    if loaded:
        # The full recording and rviz under Xvfb, as a user who watches and records.
        command += ["record:=true", "bag:=" + bag, "rviz:=true"]
        display = ":97"
        extra.append(subprocess.Popen(["Xvfb", display, "-screen", "0", "1024x768x24", "-nolisten", "tcp"],
                                      stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True))
        env.update(DISPLAY=display, LIBGL_ALWAYS_SOFTWARE="1")
        time.sleep(1.0)
        extra += busy_loops()
    launch = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env,
                              start_new_session=True)
    if not loaded:
        # Only what is analysed is recorded.
        extra.append(subprocess.Popen(["rosbag", "record", "-O", bag, "/finger/device/state", "/finger/pose",
                                       "/diagnostics", "__name:=bench_recorder"], stdout=subprocess.DEVNULL,
                                      stderr=subprocess.DEVNULL, start_new_session=True))
    time.sleep(4.0)  # nodes up, script not yet started long (script_delay 2 s after the launch's epoch)
    cpu_start, wall_start = cpu_seconds(descendants(launch.pid)), time.monotonic()
    start_ns = int(time.time() * 1e9)
    time.sleep(seconds)
    end_ns = int(time.time() * 1e9)
    pids = descendants(launch.pid)
    cpu_end, wall_end = cpu_seconds(pids), time.monotonic()
    resident = resident_mb(pids, "physics_node") if name.startswith("processes") else resident_mb(pids, "manager")
    for process in [launch] + extra:
        os.killpg(process.pid, signal.SIGINT)
    for process in [launch] + extra:
        try:
            process.wait(timeout=30)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
    subprocess.run(["rosparam", "delete", "/servo/timing_csv" if servo else "/finger/device_driver/timing_csv"],
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    result = {"setup": name, "loaded": loaded, "seconds": seconds,
              "cpu_cores": (cpu_end - cpu_start) / (wall_end - wall_start), "resident_mb": resident}
    if name == HEAVY:
        result.update({"stiffness_error": None, "stiffness_error_worst": None, "jitter_N": None,
                       "jitter_worst_N": None})
    else:
        result.update(analyse(bag))
    result.update(timing(bag, latency_csv, start_ns, end_ns))
    return result


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    seconds = float(sys.argv[3]) if len(sys.argv) > 3 and sys.argv[2] == "--seconds" else 60.0
    master = subprocess.Popen(["roscore", "-p", "11411"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                              start_new_session=True)
    os.environ["ROS_MASTER_URI"] = "http://localhost:11411"
    time.sleep(3.0)
    try:
        with tempfile.TemporaryDirectory() as directory, open(sys.argv[1], "w") as out:
            for loaded in (False, True):
                for name, arguments in SETUPS:
                    result = run(name, arguments, loaded, seconds, directory)
                    brief = {k: v for k, v in result.items() if not k.endswith("_hist")}
                    print(json.dumps(brief), flush=True)
                    out.write(json.dumps(result) + "\n")
    finally:
        os.killpg(master.pid, signal.SIGINT)
        master.wait(timeout=30)
    return 0


if __name__ == "__main__":
    sys.exit(main())
