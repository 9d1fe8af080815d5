"""Every example runs (as a user runs it, in a process of its own), writes its figure, and shows
what it says it shows."""
import os
import re
import subprocess
import sys

import pytest


def run_example(root, name, out, *arguments):
    result = subprocess.run([sys.executable, os.path.join(root, "examples", name), "--out", str(out), *arguments],
                            check=True, capture_output=True, text=True, timeout=120)
    figure = out / (os.path.splitext(name)[0] + ".png")
    assert figure.stat().st_size > 20000, "no figure at " + str(figure)
    return result.stdout


def test_slide_vs_roll(root, tmp_path):
    text = run_example(root, "slide_vs_roll.py", tmp_path)
    ratios = dict(re.findall(r"^(\w+) .*rolling ratio ([\d.]+)$", text, re.M))
    assert float(ratios["god_object"]) > 0.8  # a point rolls the ball
    assert float(ratios["god_finger"]) < 0.2  # a pad slides it


def test_pinch_sweep(root, tmp_path):
    text = run_example(root, "pinch_sweep.py", tmp_path)
    point = float(re.search(r"^god_object +turn +([\d.]+) deg", text, re.M).group(1))
    turns = {float(r): float(t) for r, t in re.findall(r"r_max +([\d.]+) mm: turn +([\d.]+) deg", text)}
    assert point > 45.0  # a point lets the cylinder swing about the pinch axis
    assert turns[2.0] > 45.0 and turns[15.0] < 1.0  # a small pad does too, a large one holds it
    assert turns[10.0] < 1.0


def test_touch_mesh(root, tmp_path):
    text = run_example(root, "touch_mesh.py", tmp_path)
    radii = [float(r) for r in re.findall(r"N: r ([\d.]+) mm", text)]
    assert radii == sorted(radii) and radii[0] > 1.0 and radii[-1] == pytest.approx(10.0, abs=0.05)
    mesh = os.path.join(root, "urdf", "meshes", "mug.obj")
    text = run_example(root, "touch_mesh.py", tmp_path, mesh)
    # The mug's highest point is its rim, 4 mm thick: the sub-god-objects walking off it onto the
    # rim's sides (beyond tau_a) are dropped, those along it stay.
    counts = [int(n) for n in re.findall(r"mm, (\d+) sub-god-objects", text)]
    assert len(counts) == 6 and all(0 < n < 16 for n in counts)
