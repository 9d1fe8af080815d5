"""## 10. Human-like operator (operator.jsonl, bench/operator_bench.cpp): the pick and place, its
targets, the sheet push; the hand tasks in operator_hand.py and operator_oriented.py."""
import math

import matplotlib.pyplot as plt

from ..common import load_jsonl, percentile, table
from . import operator_hand, operator_oriented

FILE = "operator.jsonl"


class Runs:
    """operator.jsonl read once: the twist limits, the runs, the layouts in the report's order."""

    def __init__(self, ctx):
        names = ctx.names(FILE)
        self.lines = load_jsonl(ctx.path(FILE))
        self.limits = {r["layout"]: r["twist_limit_squeeze_m"] for r in self.lines if r["kind"] == "limit"}
        self.picks = self.task("pick_place")
        self.sheets = self.task("sheet_push")
        models = ctx.names("physics_step.json")["models"]
        self.layouts = ([name for name in models if name in self.limits] +
                        [name for name in self.limits if name not in models])
        self.mujoco = [name for name in self.layouts if name.startswith(names["other_simulator"])]
        self.seeds = len({r["seed"] for r in self.picks})
        self.stiffness = names["coupling_stiffness"]
        self.turn = names["cylinder_turn"]

    def task(self, task):
        return [r for r in self.lines if r["kind"] == "run" and r["task"] == task]


def section(ctx):
    if not ctx.has(FILE):
        return []
    text = ctx.prose("operator")
    runs = Runs(ctx)
    # What "held still" means: the pick and place targets' largest turn.
    still = ctx.targets.get("operator.pick_place_god_finger").params["still_rad"]
    out = [text("heading"), ""]
    out.append(text("command", seeds=runs.seeds, mujoco_command=text("mujoco_command") if runs.mujoco else "",
                    mujoco_build=text("mujoco_build") if runs.mujoco else ""))
    out.append("")
    out.append(text("pick", mujoco_pick=text("mujoco_pick", layouts=" and ".join(runs.mujoco)) if runs.mujoco else ""))
    out.append("")
    rows = []
    for layout in runs.layouts:
        limit = runs.limits[layout]
        shown = text("never_holds") if limit < 0 else (
            text("below") if limit == 0 else text("limit", squeeze_mm=limit * 1e3, force=runs.stiffness * limit))
        rows.append([layout, shown])
    out.append(table(["layout", "twist limit: squeeze (grip force)"], rows))
    out.append("")
    out += _pick_place(ctx, text, runs, still)
    out += _tremor(text, runs, still)
    _targets(ctx, text, runs, still)
    if runs.sheets:
        out += _sheet_push(text, runs)
    out += operator_hand.section(ctx, runs)
    out += operator_oriented.section(ctx, runs)
    out.append(text("not_yet", rest=text("not_yet_mujoco") if runs.mujoco else text("not_yet_plain")))
    out.append("")
    return out


def _pick_place(ctx, text, runs, still):
    rows = []
    series = {}
    for layout in runs.layouts:
        for squeeze in sorted({r["squeeze_m"] for r in runs.picks if r["layout"] == layout}):
            group = [r for r in runs.picks if r["layout"] == layout and r["squeeze_m"] == squeeze]
            success = sum(r["placed"] for r in group) / len(group)
            turns = [r["max_turn_rad"] for r in group]
            held = sum(r["max_turn_rad"] <= still for r in group) / len(group)
            limit = runs.limits[layout]
            low = f"{0.75 * squeeze / limit:.2f}" if limit > 0 else "-"
            target = any(r["target"] for r in group)
            series.setdefault(layout, []).append((squeeze * 1e3, success, percentile(turns, 0.5), target))
            rows.append([layout, text("target_squeeze", squeeze_mm=squeeze * 1e3) if target else f"{squeeze * 1e3:.1f}",
                         low, f"{100 * success:.0f} %", f"{100 * held:.0f} %",
                         f"{percentile(turns, 0.5):.3f} / {percentile(turns, 0.9):.3f} / {max(turns):.3f}",
                         f"{1e3 * percentile([r['max_slip_m'] for r in group], 0.5):.2f}",
                         f"{percentile([r['mean_grip_force_N'] for r in group], 0.5):.2f}"])
    out = [table(["layout", "squeeze (mm)", "low point / twist limit", "success", f"turn <= {still:g} rad",
                  "turn (rad) median / p90 / max", "slip (mm) median", "grip force (N) median"], rows), ""]
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.8))
    for layout, points in series.items():
        plain = [p for p in points if not p[3]]
        axes[0].plot([p[0] for p in plain], [100 * p[1] for p in plain], marker="o", label=layout)
        axes[1].plot([p[0] for p in plain], [max(p[2], 1e-4) for p in plain], marker="o", label=layout)
    axes[0].set_xlabel("squeeze (mm)")
    axes[0].set_ylabel("success (%)")
    axes[1].set_xlabel("squeeze (mm)")
    axes[1].set_ylabel("median turn (rad, floor 1e-4)")
    axes[1].set_yscale("log")
    axes[0].legend(fontsize=8)
    return out + [ctx.figures.save("operator_pick_place.png"), ""]


def _tremor(text, runs, still):
    """What separates the target squeeze's runs that turned from those that held still: the
    tremor's peak acceleration per axis, A (2 pi f)^2, whose inertial torque m a x adds to
    gravity's m g x at the grip's lever x."""
    out = []

    def acceleration(r):
        return r["tremor_m"] * (2 * math.pi * r["tremor_hz"]) ** 2

    for layout in runs.layouts:
        group = [r for r in runs.picks if r["layout"] == layout and r["target"] and "tremor_m" in r]
        turned = [r for r in group if r["max_turn_rad"] > still]
        held = [r for r in group if r["max_turn_rad"] <= still]
        if not turned or not held:
            continue
        mine = [r for r in runs.picks if r["layout"] == layout]
        sure = [s for s in sorted({r["squeeze_m"] for r in mine})
                if all(r["max_turn_rad"] <= still for r in mine if r["squeeze_m"] == s)]
        margin = ""
        if sure:
            margin = text("margin", low_point=0.75 * sure[0] / runs.limits[layout], squeeze_mm=sure[0] * 1e3)
        out.append(text("tremor", layout=layout, turned=len(turned), still=still,
                        turned_low=min(map(acceleration, turned)), turned_high=max(map(acceleration, turned)),
                        still_count=len(held), still_low=min(map(acceleration, held)),
                        still_high=max(map(acceleration, held)),
                        turned_mis_low=1e3 * min(r["misalignment_m"] for r in turned),
                        turned_mis_high=1e3 * max(r["misalignment_m"] for r in turned),
                        still_mis_low=1e3 * min(r["misalignment_m"] for r in held),
                        still_mis_high=1e3 * max(r["misalignment_m"] for r in held),
                        larger=100 * max(map(acceleration, turned)) / 9.81, margin=margin))
        out.append("")
    return out


def _targets(ctx, text, runs, still):
    """The pick and place targets: god_finger's layouts at their target squeeze (placed, held
    still); more squeeze never turning soft_finger's bar more, nor dropping it."""
    for target in ctx.targets.in_section("operator"):
        if target.select.get("task") != "pick_place" or not target.select.get("target"):
            continue
        group = target.records(runs.lines)
        if group:
            success = sum(r["placed"] for r in group) / len(group)
            share = 100 * sum(r["placed"] and r["max_turn_rad"] <= still for r in group) / len(group)
            ctx.targets.checked(target, share, text("seeds", count=len(group)), target.share_verdict(share),
                                detail=text("placed", share=100 * success))
    target = ctx.targets.get("operator.soft_finger_squeeze")
    group = target.records(runs.lines)
    # The squeeze sweep (its target squeeze aside): the median turn never grows with the squeeze.
    squeezes = sorted({r["squeeze_m"] for r in group if not r["target"]})
    if squeezes:
        medians = [percentile([r["max_turn_rad"] for r in group if r["squeeze_m"] == s], 0.5) for s in squeezes]
        monotone = all(b <= a + target.params["tolerance_rad"] for a, b in zip(medians, medians[1:]))
        dropped = sum(not r["held"] for r in group)
        ctx.targets.checked(target, dropped, text("monotone_spread", squeezes=len(squeezes), seeds=runs.seeds),
                            "met" if monotone and target.met(dropped) else "missed",
                            measured=text("monotone", medians=", ".join(f"{m:.3f}" for m in medians), drops=dropped))


def _sheet_push(text, runs):
    out = [text("sheet"), ""]
    rows = []
    for layout in runs.layouts:
        for press in sorted({r["press_m"] for r in runs.sheets if r["layout"] == layout}):
            group = [r for r in runs.sheets if r["layout"] == layout and r["press_m"] == press]
            turns = [r["turn_rad"] for r in group]
            translated = 100 * sum(r["translated"] for r in group) / len(group)
            rows.append([layout, f"{press * 1e3:.1f}", f"{translated:.0f} %",
                         f"{percentile(turns, 0.5):.3f} / {percentile(turns, 0.9):.3f}",
                         f"{1e3 * percentile([r['translation_m'] for r in group], 0.5):.1f}",
                         f"{percentile([r['mean_press_N'] for r in group], 0.5):.2f}"])
    out.append(table(["layout", "press (mm)", "translated", "turn (rad) median / p90", "translation (mm) median",
                      "press (N) median"], rows))
    out.append("")
    return out
