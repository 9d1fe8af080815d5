"""Section 10's hand tasks by 3-DOF fingers: the cylinder turn and the mug grasp (operator.jsonl's
"cylinder_turn" runs without "oriented", and "mug_grasp"), with why a pad's turn stops."""
import math

import matplotlib.pyplot as plt

from ..common import percentile, table

# The layouts whose fingers carry a pad, and the one that is a point (physics_step.json's models).
PADS = "god_finger"
POINT = "god_object"


def _groups(layouts, runs):
    for layout in layouts:
        for squeeze in sorted({r["squeeze_m"] for r in runs if r["layout"] == layout}):
            yield layout, squeeze, [r for r in runs if r["layout"] == layout and r["squeeze_m"] == squeeze]


def _share(group, key):
    return sum(r[key] for r in group) / len(group)


def section(ctx, runs):
    turns = [r for r in runs.task("cylinder_turn") if not r.get("oriented")]
    mugs = runs.task("mug_grasp")
    if not turns and not mugs:
        return []
    text = ctx.prose("operator_hand")
    out = []
    turn_series = {}
    if turns:
        out += [text("turn"), ""]
        rows = []
        for layout, squeeze, group in _groups(runs.layouts, turns):
            angles = [r["turn_rad"] for r in group]
            tilts = [r["final_tilt_rad"] for r in group]
            turn_series.setdefault(layout, []).append(
                (squeeze * 1e3, _share(group, "turned"), math.degrees(percentile(angles, 0.5)),
                 percentile([r["mean_grip_force_N"] for r in group], 0.5), _share(group, "held")))
            rows.append([layout, text("squeeze", squeeze_mm=squeeze * 1e3, force=runs.stiffness * squeeze),
                         f"{100 * _share(group, 'turned'):.0f} %", f"{100 * _share(group, 'held'):.0f} %",
                         f"{math.degrees(percentile(angles, 0.1)):.1f} / {math.degrees(percentile(angles, 0.5)):.1f} / "
                         f"{math.degrees(percentile(angles, 0.9)):.1f}",
                         f"{percentile(tilts, 0.5):.3f} / {max(tilts):.3f}",
                         f"{1e3 * percentile([r['max_slip_m'] for r in group], 0.5):.2f}",
                         f"{percentile([r['mean_grip_force_N'] for r in group], 0.5):.2f}"])
        out.append(table(["layout", "squeeze (mm)", "success", "held", "turn (deg) p10 / median / p90",
                          "final tilt (rad) median / max", "slip (mm) median", "grip force (N) median"], rows))
        out.append("")
        out += _why_it_stops(text, runs, turns, turn_series)
    mug_series = {}
    if mugs:
        out += [text("mug"), ""]
        rows = []
        for layout, squeeze, group in _groups(runs.layouts, mugs):
            tilts = [r["max_tilt_rad"] for r in group]
            mug_series.setdefault(layout, []).append((squeeze * 1e3, _share(group, "lifted")))
            rows.append([layout, text("squeeze", squeeze_mm=squeeze * 1e3, force=runs.stiffness * squeeze),
                         f"{100 * _share(group, 'lifted'):.0f} %", f"{100 * _share(group, 'held'):.0f} %",
                         f"{1e3 * percentile([r['lift_height_m'] for r in group], 0.5):.1f}",
                         f"{percentile(tilts, 0.5):.3f} / {max(tilts):.3f}",
                         f"{1e3 * percentile([r['max_slip_m'] for r in group], 0.5):.2f}",
                         f"{percentile([r['mean_grip_force_N'] for r in group], 0.5):.2f}"])
        out.append(table(["layout", "squeeze (mm)", "success", "held", "lift (mm) median",
                          "max tilt (rad) median / max", "slip (mm) median", "grip force (N) median"], rows))
        out.append("")
    out += [_figure(ctx, turn_series, mug_series), ""]
    return out


def _why_it_stops(text, runs, turns, turn_series):
    """The pad against the roll, the point against the swing: from the rows above. The turn stops
    where the hand's pull along the mantle, k (R - s) sin(lag) with the target a circle of radius
    R - s about the axis (R = r + proxy radius) leading the cylinder by `lag`, times r, meets what
    the pads resist the roll with, N a_eff (a 3-DOF pad sticks to the mantle, so the cylinder's lag
    behind its target is the finger's)."""
    radius, mu = runs.turn["radius"], runs.turn["friction"]
    face = radius + runs.turn["proxy_radius"]
    notes = []
    for layout, points in turn_series.items():
        if not layout.startswith(PADS) or len(points) < 2:
            continue
        best = max(points, key=lambda p: p[1])
        hardest = points[-1]
        if hardest[2] < best[2] - 5:
            notes.append(text("note", layout=layout, best=best[2], best_mm=best[0], hardest=hardest[2],
                              hardest_mm=hardest[0]))
    if not notes:
        return []
    levers = []
    for layout, points in turn_series.items():
        if not layout.startswith(PADS):
            continue
        for squeeze_mm, _, turn_deg, grip, held in points:
            lag = math.radians(90.0 - turn_deg)
            if lag < math.radians(5.0) or held < 1.0:
                continue  # turned (its pull is not the limit), or dropped (its lag is not the fingers')
            pull = runs.stiffness * (face - 1e-3 * squeeze_mm) * math.sin(lag)
            levers.append(text("lever", layout=layout, squeeze_mm=squeeze_mm, lag=math.degrees(lag), pull=pull,
                               grip=grip, a_eff=1e3 * pull * radius / grip))
    squeezes = sorted({r["squeeze_m"] for r in turns})
    point = ""
    if any(r["layout"] == POINT for r in turns):
        point = text("point", layout=POINT,
                     turn=math.degrees(percentile([r["turn_rad"] for r in turns if r["layout"] == POINT], 0.5)),
                     tilt=percentile([r["final_tilt_rad"] for r in turns if r["layout"] == POINT], 0.5))
    return [text("limit", notes="; ".join(notes), mu_r=1e3 * mu * radius, face=1e3 * face,
                 pulls=", ".join(text("pull_at", pull=runs.stiffness * (face - s), squeeze_mm=1e3 * s)
                                 for s in squeezes if s < face),
                 levers="; ".join(levers), point=point), ""]


def _figure(ctx, turn_series, mug_series):
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.8))
    for layout, points in turn_series.items():
        axes[0].plot([p[0] for p in points], [100 * p[1] for p in points], marker="o", label=layout)
        axes[1].plot([p[0] for p in points], [p[2] for p in points], marker="o", label=layout)
    for layout, points in mug_series.items():
        axes[2].plot([p[0] for p in points], [100 * p[1] for p in points], marker="o", label=layout)
    axes[1].axhline(90.0, color="grey", linestyle="--", linewidth=1)
    axes[0].set_title("pinch and turn: success", fontsize=9)
    axes[1].set_title("pinch and turn: median turn (90 deg commanded)", fontsize=9)
    axes[2].set_title("hand grasp (mug): success", fontsize=9)
    for axis in axes:
        axis.set_xlabel("squeeze (mm)")
    axes[0].set_ylabel("success (%)")
    axes[1].set_ylabel("turn (deg)")
    axes[2].set_ylabel("success (%)")
    axes[0].legend(fontsize=8)
    return ctx.figures.save("operator_turn_grasp.png")
