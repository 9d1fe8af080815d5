"""Section 10's cylinder turn by oriented fingers (operator.jsonl's "cylinder_turn" runs with
"oriented"), beside the 3-DOF fingers' success, and its targets."""
import math

from ..common import percentile, table


def section(ctx, runs):
    turns = [r for r in runs.task("cylinder_turn") if r.get("oriented")]
    if not turns:
        return []
    text = ctx.prose("operator_oriented")
    flat = [r for r in runs.task("cylinder_turn") if not r.get("oriented")]
    out = [text("intro"), ""]
    rows = []
    for layout in runs.layouts:
        for squeeze in sorted({r["squeeze_m"] for r in turns if r["layout"] == layout}):
            group = [r for r in turns if r["layout"] == layout and r["squeeze_m"] == squeeze]
            angles = [r["turn_rad"] for r in group]
            tilts = [r["final_tilt_rad"] for r in group]
            share = sum(r["turned"] for r in group) / len(group)
            same = [r for r in flat if r["layout"] == layout and r["squeeze_m"] == squeeze]
            rows.append([layout, f"{squeeze * 1e3:.1f} ({runs.stiffness * squeeze:.1f} N)", f"{100 * share:.0f} %",
                         f"{100 * sum(r['turned'] for r in same) / len(same):.0f} %" if same else "-",
                         f"{100 * sum(r['held'] for r in group) / len(group):.0f} %",
                         f"{math.degrees(percentile(angles, 0.1)):.1f} / {math.degrees(percentile(angles, 0.5)):.1f} / "
                         f"{math.degrees(percentile(angles, 0.9)):.1f}",
                         f"{percentile(tilts, 0.5):.3f} / {max(tilts):.3f}",
                         f"{percentile([r['mean_grip_force_N'] for r in group], 0.5):.2f}"])
    out.append(table(["layout", "squeeze (mm)", "success", "3-DOF success", "held", "turn (deg) p10 / median / p90",
                      "final tilt (rad) median / max", "grip force (N) median"], rows))
    out += ["", text("slip"), ""]
    for target in ctx.targets.in_section("operator"):
        if target.select.get("task") != "cylinder_turn":
            continue
        group = target.records(runs.lines)
        if group:
            share = sum(r["turned"] for r in group) / len(group)
            ctx.targets.checked(target, 100 * share, text("seeds", count=len(group)), target.plain_verdict(100 * share))
    return out
