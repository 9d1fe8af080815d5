"""## 7. MuJoCo baseline (mujoco_baseline.json): each scenario's step and metrics, god_finger's
and god_object's against MuJoCo at condim 3, 4 and 6."""
from .. import benchmark_targets
from ..common import load_benchmarks, table

FILE = "mujoco_baseline.json"


def section(ctx):
    if not ctx.has(FILE):
        return []
    names = ctx.names(FILE)
    text = ctx.prose("mujoco")
    results = load_benchmarks(ctx.path(FILE))
    out = [text("heading"), "", text("command")]
    system, against = names["headline"]
    for s, scenario in names["scenarios"]:
        metrics = names["metrics"][scenario]
        rows = []
        steps_us = {}
        for name, pattern in names["systems"]:
            entry = results.get(pattern.format(scenario=s))
            if entry is None:
                continue
            _, counters, _ = entry
            steps_us[name] = entry[0] / 1e3 / counters["steps"]
            row = [name, f"{steps_us[name]:.1f}"]
            for key, _, scale, fmt in metrics:
                row.append(fmt.format(counters[key] * scale) if key in counters else "")
            row.append(f"{counters['mean_contacts']:.1f} / {counters['mean_rows']:.1f}" if "mean_rows" in counters
                       else "")
            rows.append(row)
        if not rows:
            continue
        ratio = steps_us[system] / steps_us[against] if system in steps_us and against in steps_us else float("nan")
        out += ["", text("scenario", scenario=scenario, system=system, against=against, ratio=ratio), "",
                table(["system", "step (us)"] + [label for _, label, _, _ in metrics] +
                      ["MuJoCo contacts / rows per step"], rows)]
    benchmark_targets.measure_section(ctx, "mujoco")
    return out + [""]
