"""## 8. Scale: objects and fingers (mujoco_baseline.json's scale benchmarks); also bench/SCALE.md
on its own (scripts/bench --scale)."""
import matplotlib.pyplot as plt

from .. import benchmark_targets
from ..common import load_benchmarks, repetitions, table

FILE = "mujoco_baseline.json"


def section(ctx, figure_name="scale_step_vs_objects.png"):
    if not ctx.has(FILE):
        return []
    names = ctx.names(FILE)
    text = ctx.prose("scale")
    path = ctx.path(FILE)
    results = load_benchmarks(path)
    p50s = repetitions(path, "p50_us")
    out = [text("heading"), "", text("command")]
    rows = []
    p50 = {}
    for s, objects, fingers in names["scale_scenes"]:
        for system, pattern in names["scale_systems"]:
            name = pattern.format(scene=s)
            entry = results.get(name)
            if entry is None:
                continue
            _, counters, _ = entry
            p50[(objects, fingers, system)] = counters["p50_us"]
            reps = p50s.get(name, [counters["p50_us"]])
            rows.append([objects, fingers, system, f"{counters['p50_us']:.1f} ({min(reps):.1f}-{max(reps):.1f})",
                         f"{counters['p99_us']:.1f}", f"{counters.get('mean_solver_iterations', float('nan')):.1f}"])
    if not rows:
        return []
    out += ["", table(["objects", "fingers", "system", "step p50 (us)", "step p99 (us)", "iterations"], rows)]
    benchmark_targets.measure_section(ctx, "scale")
    plt.figure(figsize=(6.4, 4.0))
    for system, _ in names["scale_systems"]:
        points = sorted((objects, value) for (objects, fingers, name), value in p50.items()
                        if name == system and fingers == (1 if objects == 1 else 2))
        if points:
            plt.plot([p[0] for p in points], [p[1] for p in points], marker="o", label=system)
    plt.xscale("log")
    plt.yscale("log")
    plt.xlabel("objects on the table (2 fingers; 1 with 1 object)")
    plt.ylabel("step p50 (us)")
    plt.grid(True, which="both", alpha=0.3)
    plt.legend()
    out += ["", ctx.figures.save(figure_name), ""]
    return out
