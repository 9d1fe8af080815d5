"""## 15. From Python: god_finger.World against the same calls in C++ (python_overhead.jsonl,
bench/python_overhead.py): each workload's paired rounds, and its target on their ratio or their
difference (the target's params.combine)."""
from ..common import Measure, load_jsonl, table

FILE = "python_overhead.jsonl"


def section(ctx):
    if not ctx.has(FILE):
        return []
    text = ctx.prose("python")
    base, candidate = ctx.names(FILE)["sides"]
    runs = load_jsonl(ctx.path(FILE))
    commit = runs[0].get("commit", "") if runs else ""
    out = [text("heading"), "", text("command", measured_at=text("measured_at", commit=commit) if commit else ""), ""]
    rows = []
    for target in ctx.targets.in_section("python"):
        by_round = {}  # a round's best run of each side
        for r in target.records(runs):
            sides = by_round.setdefault(r["round"], {})
            sides[r["side"]] = min(sides.get(r["side"], r[target.key]), r[target.key])
        paired = [v for v in by_round.values() if base in v and candidate in v]
        if not paired:
            continue
        cpp = sorted(v[base] for v in paired)
        py = sorted(v[candidate] for v in paired)
        ratios = sorted(v[candidate] / v[base] for v in paired)
        excess = sorted(v[candidate] - v[base] for v in paired)
        middle = len(paired) // 2
        rows.append([target.select["workload"], str(len(paired)), f"{cpp[middle]:.3f} ({cpp[0]:.3f}-{cpp[-1]:.3f})",
                     f"{py[middle]:.3f} ({py[0]:.3f}-{py[-1]:.3f})", f"{ratios[middle]:.3f}",
                     f"{excess[middle]:+.3f}"])
        values = ratios if target.params["combine"] == "ratio" else excess
        ctx.targets.measured(target, Measure(values[middle], values[0], values[-1],
                                             text("rounds", count=len(paired))))
    out += [table(["workload", "rounds", "C++ us/step (range)", "Python us/step (range)", "Python / C++ (median)",
                   "Python - C++ us/step (median)"], rows), ""]
    return out
