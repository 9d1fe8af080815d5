#!/usr/bin/env python3
"""A pinch and lift from Python, swept over the pad's largest radius r_max: two fingers press
the flat ends of a lying cylinder (urdf/scenes/table_cylinder.urdf, 150 g), lift it 10 cm and
hold it. The fingers grip 1.5 cm beside the axis, so the lifted cylinder's weight turns it about
the pinch axis. A point contact (god_object) cannot resist that turn; a pad resists it with its
area, more the larger it can grow. One figure: the cylinder's turn
about the pinch axis and its height at the end, against r_max, with the point contact's turn.

    python3 examples/pinch_sweep.py [--out DIR]       # writes DIR/pinch_sweep.png
"""
import argparse
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import god_finger  # noqa: E402

R_MAX = [0.002, 0.003, 0.004, 0.005, 0.006, 0.008, 0.010, 0.015]  # m
CLOSE, LIFT_START, LIFT_END, END = 1.0, 1.5, 3.5, 6.0  # s
# m: the fingers grip the flat ends 1.5 cm beside the axis, at its height. Lifted, the cylinder's
# weight (1.47 N) turns it about the pinch axis with 22 mN m, which only the pads' torsional
# friction holds: about mu N (2/3) r per finger, so a pad of a few millimetres lets it swing.
OFFSET = 0.015


def hand(t, side):
    """Like the paper's Fig. 8 (scenarios' pinch_cylinder), off the axis: close along x, wait, lift."""
    x = 0.075 + (0.053 - 0.075) * min(t / CLOSE, 1.0)
    z = 0.03 + 0.1 * min(max((t - LIFT_START) / (LIFT_END - LIFT_START), 0.0), 1.0)
    return [side * x, OFFSET - 0.0005 * side, z]


def turn_about_x(q0, q):
    """The rotation of orientation q from q0 (x, y, z, w) about the world's x axis (rad)."""
    w0, v0 = q0[3], np.array(q0[:3])
    w1, v1 = q[3], np.array(q[:3])
    # relative rotation q0^-1 q
    w = w0 * w1 + v0 @ v1
    v = w0 * v1 - w1 * v0 - np.cross(v0, v1)
    return 2.0 * math.atan2(v[0], w)


def pinch(model, r_max):
    world = god_finger.World(god_finger.data_path("urdf", "scenes", "table_cylinder.urdf"), model=model, r_max=r_max)
    fingers = [world.add_finger(hand(0.0, side)) for side in (-1, 1)]
    start = world.body("cylinder")
    steps = int(round(END / world.params["time_step"]))
    worst = 0.0
    for i in range(steps):
        t = (i + 1) * world.params["time_step"]
        for finger, side in zip(fingers, (-1, 1)):
            world.set_target(finger, hand(t, side))
        world.step()
        if t > LIFT_END:
            worst = max(worst, abs(turn_about_x(start.orientation, world.body("cylinder").orientation)))
    end = world.body("cylinder")
    return math.degrees(worst), 100 * (end.center_of_mass[2] - start.center_of_mass[2])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default=".", help="folder of the figure (default: here)")
    args = parser.parse_args()

    point_turn, point_height = pinch("god_object", 0.01)
    print("god_object           turn %6.2f deg, height %5.1f cm" % (point_turn, point_height))
    turns, heights = [], []
    for r_max in R_MAX:
        turn, height = pinch("god_finger", r_max)
        turns.append(turn)
        heights.append(height)
        print("god_finger r_max %4.1f mm: turn %6.2f deg, height %5.1f cm" % (1000 * r_max, turn, height))

    fig, (ax_turn, ax_height) = plt.subplots(1, 2, figsize=(10, 4))
    mm = [1000 * r for r in R_MAX]
    ax_turn.plot(mm, turns, "o-", label="god_finger")
    ax_turn.axhline(point_turn, color="C3", ls="--", label="god_object (a point)")
    ax_turn.set_xlabel("r_max (mm)")
    ax_turn.set_ylabel("largest turn about the pinch axis after the lift (deg)")
    ax_turn.legend()
    ax_height.plot(mm, heights, "o-", label="god_finger")
    ax_height.axhline(point_height, color="C3", ls="--", label="god_object")
    ax_height.set_xlabel("r_max (mm)")
    ax_height.set_ylabel("rise of its centre of mass at %.0f s (cm)" % END)
    ax_height.set_ylim(bottom=0)
    ax_height.legend()
    for ax in (ax_turn, ax_height):
        ax.grid(True, alpha=0.3)
    fig.suptitle("Pinch and lift a 150 g cylinder by its ends: the pad's radius against its turn")
    fig.tight_layout()
    os.makedirs(args.out, exist_ok=True)
    path = os.path.join(args.out, "pinch_sweep.png")
    fig.savefig(path, dpi=100)
    print("wrote", path)


if __name__ == "__main__":
    main()
