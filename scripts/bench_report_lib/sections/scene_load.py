"""## 9. Loading a scanned-size concave object (scene_load.json): each load against its target."""
from .. import benchmark_targets
from ..common import NS_PER, load_benchmarks, table

FILE = "scene_load.json"


def section(ctx):
    if not ctx.has(FILE):
        return []
    names = ctx.names(FILE)
    text = ctx.prose("scene_load")
    results = load_benchmarks(ctx.path(FILE))
    out = [text("heading"), "", text("command"), ""]
    rows = []
    for load in names["loads"]:
        target = ctx.targets.get(load["target"])
        if target.benchmark not in results:
            continue
        time_ns, counters, _ = results[target.benchmark]
        value_ms = time_ns / 1e6
        goal_ms = target.goal * NS_PER[target.unit] / NS_PER["ms"]
        rows.append([load["label"], f"{counters.get('triangles', 0):.0f}", f"{value_ms:.0f}",
                     f"{target.comparison} {goal_ms:.0f}", _verdict(target, value_ms, goal_ms)])
    benchmark_targets.measure_section(ctx, "scene_load")
    out.append(table(["load", "triangles", "time (ms)", "goal (ms)", "verdict"], rows))
    return out + [""]


def _verdict(target, value, goal):
    """A benchmark's target is `value <= goal` (bench_report_lib.targets checks it)."""
    if value <= goal:
        return "met"
    return f"missed by {value / goal:.2f}x"
