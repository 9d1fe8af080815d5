#!/usr/bin/env python3
"""The Python module's overhead against the same calls in C++ (issue 52's targets, in
bench/targets.yaml: python.step_block and python.loop): 10,000 steps of the slide scene by one
step(10000) against C++'s loop, and a Python loop that sets the target, steps once and reads the
finger, per step above C++'s. Both sides run the same workloads (bench/python_overhead.cpp is
the C++ side), interleaved round by round: C++, Python, C++, Python, so that the machine's noise
falls on both alike.

    bench/python_overhead.py PROGRAM OUT.jsonl [ROUNDS]

PROGRAM is the C++ side's binary. One JSON line per run into OUT.jsonl: round, repeat, side (cpp
or python), workload, steps, us_per_step (each round runs each side REPEATS times, alternating). scripts/bench --python runs it; bench_report shows the
medians and the targets.
"""
import json
import subprocess
import sys
import time

import god_finger

STEPS = 10000
# Runs per side in a round, alternating: a round's time of a side is its best (a noisy machine only
# ever adds time), the report's figure the median of the rounds'.
REPEATS = 3


def python_side(scene, workload):
    world = god_finger.World(scene)
    start = [-0.06, 0.0, 0.0525]
    finger = world.add_finger(start)
    if workload == "step_block":
        world.set_target(finger, [start[0] + 0.04, 0.0, start[2]])
        begin = time.perf_counter()
        world.step(STEPS)
    else:
        begin = time.perf_counter()
        for i in range(STEPS):
            world.set_target(finger, [start[0] + 0.05 * ((i + 1) * 0.001), 0.0, start[2]])
            world.step()
            state = world.finger(finger)
    seconds = time.perf_counter() - begin
    state = world.finger(finger)
    checksum = state.force[0] + state.position[0]
    return {"workload": workload, "steps": STEPS, "us_per_step": 1e6 * seconds / STEPS, "checksum": checksum}


def main():
    program, out = sys.argv[1], sys.argv[2]
    rounds = int(sys.argv[3]) if len(sys.argv) > 3 else 7
    scene = god_finger.data_path("urdf", "scenes", "table_sphere.urdf")
    with open(out, "w") as lines:
        for round_ in range(1, rounds + 1):
            for workload in ("step_block", "loop"):
                best = {}
                for repeat in range(REPEATS):
                    cpp = json.loads(subprocess.run([program, scene, workload, str(STEPS)], check=True,
                                                    capture_output=True, text=True).stdout)
                    py = python_side(scene, workload)
                    for side, run in (("cpp", cpp), ("python", py)):
                        run.update({"round": round_, "repeat": repeat, "side": side})
                        lines.write(json.dumps(run) + "\n")
                        best[side] = min(best.get(side, run["us_per_step"]), run["us_per_step"])
                    if cpp["checksum"] != py["checksum"]:
                        raise SystemExit("python_overhead: the two sides ran different physics")
                print("round %d %-10s best of %d: cpp %7.3f us/step  python %7.3f us/step" %
                      (round_, workload, REPEATS, best["cpp"], best["python"]), flush=True)


if __name__ == "__main__":
    main()
