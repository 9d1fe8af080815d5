#!/usr/bin/env python3
"""The paper's Fig. 5 from Python: a finger pushes a ball on a table. With a point contact
(god_object) the ball rolls under the finger; with a finger pad (god_finger) the pad's torsional
and tilt resistance makes it slide with the finger. One figure: the ball's translation and the
arc it rolled, against time, for both models.

    python3 examples/slide_vs_roll.py [--out DIR]     # writes DIR/slide_vs_roll.png
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import god_finger  # noqa: E402

BALL_RADIUS = 0.04  # m, urdf/scenes/table_sphere.urdf


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default=".", help="folder of the figure (default: here)")
    args = parser.parse_args()

    fig, axes = plt.subplots(1, 2, figsize=(10, 4), sharey=True)
    for ax, model in zip(axes, ["god_object", "god_finger"]):
        result = god_finger.run_experiment("slide", model)
        s = result["series"]
        dt = np.diff(s["t"], prepend=0.0)
        translation = np.hypot(s["x"] - s["x"][0], s["y"] - s["y"][0])
        rolled_arc = BALL_RADIUS * np.cumsum(np.hypot(s["wx"], s["wy"]) * dt)
        ax.plot(s["t"], 100 * translation, label="translation of the ball")
        ax.plot(s["t"], 100 * rolled_arc, "--", label="arc rolled (r x angle)")
        ax.set_title("%s: rolling ratio %.2f" % (model, result["metrics"]["rolling_ratio"]))
        ax.set_xlabel("time (s)")
        ax.grid(True, alpha=0.3)
        print("%-10s translation %.1f cm, rolled %.1f cm, rolling ratio %.2f" %
              (model, 100 * translation[-1], 100 * rolled_arc[-1], result["metrics"]["rolling_ratio"]))
    axes[0].set_ylabel("cm")
    axes[0].legend(loc="upper left")
    fig.suptitle("A finger pushes a ball: a point rolls it, a pad slides it (paper, Fig. 5)")
    fig.tight_layout()
    os.makedirs(args.out, exist_ok=True)
    path = os.path.join(args.out, "slide_vs_roll.png")
    fig.savefig(path, dpi=100)
    print("wrote", path)


if __name__ == "__main__":
    main()
