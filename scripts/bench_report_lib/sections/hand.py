"""### 5b. The servo loop with a hand of N fingers against the platform's floor of the same run
(hand_loop.jsonl: bench/hand_loop_bench, rounds interleaved by scripts/bench)."""
from ..common import Measure, load_jsonl, percentile, table
from ..targets import value_at

FILE = "hand_loop.jsonl"


def section(ctx):
    if not ctx.has(FILE):
        return []
    text = ctx.prose("hand")
    runs = load_jsonl(ctx.path(FILE))
    seconds = runs[0]["seconds"] if runs else 0
    commits = sorted({r["commit"] for r in runs if "commit" in r})
    command = text("command", rounds=len({r["round"] for r in runs}), seconds=seconds)
    if commits:
        command += text("commits", commits=", ".join(commits))
        command += text("commits_dirty") if any(c.endswith("+") for c in commits) else text("commits_end")
    out = [text("heading"), "", command]
    rows = []
    for r in runs:
        rows.append([r["round"], r["fingers"], f"{r['loadavg_1min']:.2f}", "yes" if r["realtime"] else "no",
                     r["ticks"], r["overruns"], r["untracked_samples"],
                     f"{r['floor_us_p50']:.1f} / {r['floor_us_p99']:.1f}",
                     f"{r['period_us_p50']:.1f} / {r['period_us_p99']:.1f} / {r['period_us_max']:.1f}",
                     f"{r['step_us_p50']:.1f} / {r['step_us_p99']:.1f}", f"{r['p99_over_floor_us']:+.1f}"])
    out += ["", table(["round", "fingers", "load", "real time", "ticks", "overruns", "untracked samples",
                       "floor p50 / p99 (us)", "period p50 / p99 / max (us)", "step p50 / p99 (us)",
                       "period p99 - floor p99 (us)"], rows), ""]
    for target in ctx.targets.in_section("hand"):
        # Over the interleaved rounds: their median and range.
        values = sorted(value_at(r, target.key) / 1e3 for r in target.records(runs))
        if values:
            ctx.targets.measured(target, Measure(percentile(values, 0.5), values[0], values[-1],
                                                 text("rounds", count=len(values))))
    return out
