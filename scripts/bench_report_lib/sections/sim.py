"""## 4. Speed against error: time step x solver iterations x float32/float64
(sim_accuracy.jsonl), and the trajectories' errors against the reference run."""
import math

import matplotlib.pyplot as plt

from ..common import load_jsonl, table

FILE = "sim_accuracy.jsonl"


def sim_errors(reference, candidates):
    """Sets each candidate's error_mm (largest distance of the centre of mass from the reference
    run's) and angle_rad from the trajectories; a compact copy (--keep) has them already."""
    if "trajectory" not in reference:
        return
    ref = {round(sample[0], 6): sample for sample in reference["trajectory"]}
    for r in candidates:
        if "trajectory" not in r:
            continue
        error = 0.0
        angle = 0.0
        for sample in r["trajectory"]:
            other = ref.get(round(sample[0], 6))
            if other is None:
                continue
            error = max(error, math.dist(sample[1:4], other[1:4]))
            dot = abs(sum(a * b for a, b in zip(sample[4:8], other[4:8])))
            angle = max(angle, 2.0 * math.acos(min(1.0, dot)))
        if r["nan"] or any(not math.isfinite(v) for s in r["trajectory"] for v in s):
            error = angle = float("inf")
        r["error_mm"] = 1e3 * error
        r["angle_rad"] = angle


def pareto(points):
    """Indices of points (cost, error) not dominated by another (lower cost and lower error)."""
    front = []
    for i, (cost, error) in enumerate(points):
        if not any(c <= cost and e <= error and (c, e) != (cost, error) for c, e in points):
            front.append(i)
    return front


def summary(text, names, candidates, front):
    """Where the default setting lies, what a shorter step buys, and whether float32 reaches the
    front."""
    default_setting = names["default"]

    def find(dt):
        return next((i for i, r in enumerate(candidates) if r["precision"] == default_setting["precision"]
                     and abs(r["dt"] - dt) < 1e-9 and r["iterations"] == default_setting["iterations"]), None)
    default = find(default_setting["dt"])
    shorter = find(names["shorter_dt"])
    words = []
    if default is not None:
        r = candidates[default]
        words.append(text("default", precision=default_setting["precision"], dt_ms=1e3 * default_setting["dt"],
                          iterations=default_setting["iterations"],
                          not_="" if default in front else text("default_not"),
                          error=r["error_mm"], cost=r["compute_s_per_sim_s"]))
        if shorter is not None:
            h = candidates[shorter]
            if h["error_mm"] > 0:
                words.append(text("shorter", dt_ms=1e3 * names["shorter_dt"], iterations=default_setting["iterations"],
                                  ratio=r["error_mm"] / h["error_mm"],
                                  cost=h["compute_s_per_sim_s"] / r["compute_s_per_sim_s"]))
    on_front = [candidates[i] for i in sorted(front) if candidates[i]["precision"] == "float32"]
    if on_front:
        words.append(text("float32_on_front", settings=", ".join(
            text("float32_setting", dt_ms=1e3 * r["dt"], iterations=r["iterations"]) for r in on_front)))
    else:
        words.append(text("float32_nowhere"))
    return " ".join(words)


def section(ctx):
    names = ctx.names(FILE)
    text = ctx.prose("sim")
    runs = load_jsonl(ctx.path(FILE))
    out = [text("heading"), "", text("command")]
    for scenario in sorted({r["scenario"] for r in runs}):
        group = [r for r in runs if r["scenario"] == scenario]
        reference = next((r for r in group if r.get("reference")), None)
        if reference is None:
            continue
        candidates = [r for r in group if not r.get("reference")]
        sim_errors(reference, candidates)
        points = [(r["compute_s_per_sim_s"], r["error_mm"]) for r in candidates]
        front = set(pareto(points))
        rows = [[r["precision"], f"{1e3 * r['dt']:g}", r["iterations"], f"{r['compute_s_per_sim_s']:.4f}",
                 f"{r['error_mm']:.3g}", f"{r['angle_rad']:.3g}", "*" if i in front else ""]
                for i, r in enumerate(candidates)]
        rows.sort(key=lambda row: (row[0], float(row[1]), row[2]))
        out += ["", text("scenario", scenario=scenario, cost=reference["compute_s_per_sim_s"]), "",
                table(["precision", "dt (ms)", "iterations", "compute s / sim s", "position error (mm)",
                       "orientation error (rad)", "Pareto"], rows), ""]
        out += [summary(text, names, candidates, front), ""]
        plt.figure(figsize=(6.4, 4))
        for precision, marker in (("float64", "o"), ("float32", "^")):
            xs = [r["compute_s_per_sim_s"] for r in candidates if r["precision"] == precision]
            ys = [max(r["error_mm"], 1e-6) for r in candidates if r["precision"] == precision]
            plt.loglog(xs, ys, marker, label=precision, alpha=0.7)
        front_points = sorted(points[i] for i in front if math.isfinite(points[i][1]))
        plt.loglog([p[0] for p in front_points], [max(p[1], 1e-6) for p in front_points], "k-", label="Pareto front")
        plt.xlabel("compute seconds per simulated second")
        plt.ylabel("trajectory error (mm)")
        plt.title(scenario)
        plt.legend(fontsize=8)
        plt.grid(True, which="both", alpha=0.3)
        out += [ctx.figures.save(f"sim_error_vs_cost_{scenario}.png"), ""]
    return out
