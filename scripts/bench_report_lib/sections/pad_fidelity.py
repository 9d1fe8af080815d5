"""## 6. Pad fidelity: the torques a pad holds against soft-finger physics (pad_fidelity.jsonl).
Each load (twist, tilt) is shown for the layout its target checks against its analytic model."""
import math

import matplotlib.pyplot as plt

from ..common import load_jsonl, table

FILE = "pad_fidelity.jsonl"
MARKERS = {"god_object": "x", "soft_finger": "v", "god_finger": "o", "god_finger/points": "s"}
# Each load's analytic model of the torque held: its name and its value at (mu, N, a).
MODELS = {"twist": ("uniform disk", lambda mu, n, a: 2.0 / 3.0 * mu * n * a),
          "tilt": ("N a", lambda mu, n, a: n * a)}


def section(ctx):
    if not ctx.has(FILE):
        return []
    text = ctx.prose("pad_fidelity")
    runs = load_jsonl(ctx.path(FILE))
    out = [text("heading"), "", text("command")]
    capacity = [r for r in runs if r["kind"] == "capacity"]
    layouts = []
    for r in capacity:
        if r["layout"] not in layouts:
            layouts.append(r["layout"])
    for target in ctx.targets.in_section("pad_fidelity"):
        load, checked = target.select["load"], target.select["layout"]
        model, analytic = MODELS[load]
        rows_by_force = _figure(capacity, layouts, load, checked)
        out += ["", text("load", load=load.capitalize()), "", ctx.figures.save(f"pad_{load}_capacity.png"), ""]
        rows = []
        worst = 0.0
        for force in sorted(rows_by_force):
            row = [f"{force:.1f}"]
            for layout in layouts:
                entry = rows_by_force[force].get(layout)
                if entry is None:
                    row.append("")
                    continue
                torque, radius, mu, n = entry
                expected = analytic(mu, n, radius)
                row.append(f"{1e3 * torque:.2f} ({torque / expected:.2f})")
                if layout == checked:
                    worst = max(worst, abs(torque / expected - 1.0))
            rows.append(row)
        out += [text("torques", model=model), "", table(["N (N)"] + layouts, rows), ""]
        # Deterministic (a bisection of simulated runs): the same on every run and machine.
        ctx.targets.checked(target, 100 * worst, target.spread, target.excess_verdict(100 * worst))
    creep = [r for r in runs if r["kind"] == "creep"]
    if creep:
        rows = [[r["layout"], r["iterations"], f"{r['pinch_rotation']:.2g}", f"{r['pinch_held_s']:.1f}",
                 f"{r['pinch_step_us']:.1f}", f"{r['twist_hold_rotation']:.2g}"] for r in creep]
        out += [text("creep"), "",
                table(["layout", "iterations", "pinch turn (rad)", "pinch held (s)", "pinch step (us)",
                       "twist hold turn (rad)"], rows), ""]
    return out


def _figure(capacity, layouts, load, reference_layout):
    """Plots the capacity of every layout and the analytic curves at the reference layout's
    measured N and a; returns nominal force -> layout -> (torque, radius, mu, N)."""
    rows_by_force = {}
    plt.figure(figsize=(6, 4))
    for layout in layouts:
        points = sorted((r["normal_force"], r["torque"], r["contact_radius"], r["friction"],
                         r.get("nominal_force", round(r["normal_force"], 1)))
                        for r in capacity if r["load"] == load and r["layout"] == layout)
        plt.plot([p[0] for p in points], [1e3 * p[1] for p in points], MARKERS.get(layout, "o"), label=layout)
        for force, torque, radius, mu, nominal in points:
            rows_by_force.setdefault(nominal, {})[layout] = (torque, radius, mu, force)
    reference = sorted((r["normal_force"], r["contact_radius"], r["friction"]) for r in capacity
                       if r["load"] == load and r["layout"] == reference_layout)
    forces = [p[0] for p in reference]
    if load == "twist":
        curves = (("uniform disk (2/3) mu N a", 2.0 / 3.0, "-"), ("Hertz (3 pi/16) mu N a", 3 * math.pi / 16, "--"),
                  ("ring of 8 + centre (8/9) mu N a", 8.0 / 9.0, ":"))
        for label, factor, style in curves:
            plt.plot(forces, [1e3 * factor * mu * n * a for n, a, mu in reference], "k" + style, label=label)
    else:
        plt.plot(forces, [1e3 * n * a for n, a, _ in reference], "k-", label="N a")
    plt.xlabel("normal force N (N)")
    plt.ylabel(f"{load} torque held (mN m)")
    plt.legend(fontsize=7)
    return rows_by_force
