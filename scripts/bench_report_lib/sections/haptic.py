"""## 5. Haptic loop: the servo loop against the topic topologies, idle and loaded
(haptic_loop.jsonl, and the platform's wake-ups of wakeup_latency.jsonl)."""
import matplotlib.pyplot as plt

from ..common import Measure, load_jsonl, table
from ..targets import value_at

FILE = "haptic_loop.jsonl"
PLATFORM = "wakeup_latency.jsonl"


def section(ctx):
    text = ctx.prose("haptic")
    runs = load_jsonl(ctx.path(FILE))
    seconds = runs[0]["seconds"] if runs else 0
    platform_runs = {}
    if ctx.has(PLATFORM):
        platform_runs = {bool(w.get("loaded")): w for w in load_jsonl(ctx.path(PLATFORM))}
    out = [text("heading"), "", text("command", seconds=seconds)]
    rows = []
    for r in runs:
        period, latency = r["period_us"], r["latency_us"]
        rows.append([r["setup"], "loaded" if r["loaded"] else "idle", f"{r['rate_hz']:.2f}",
                     f"{period['p50'] / 1e3:.3f} / {period['p99'] / 1e3:.3f} / {period['max'] / 1e3:.2f}",
                     f"{latency['p50'] / 1e3:.3f} / {latency['p99'] / 1e3:.3f} / {latency['max'] / 1e3:.2f}",
                     f"{r['cpu_cores']:.2f}",
                     "n/a" if r["stiffness_error"] is None else
                     f"{100 * r['stiffness_error']:.2f} % / {100 * r['stiffness_error_worst']:.1f} %",
                     "n/a" if r["jitter_N"] is None else f"{1e3 * r['jitter_N']:.1f} / {1e3 * r['jitter_worst_N']:.0f}",
                     f"{r['resident_mb']:.0f}"])
    _targets(ctx, text, runs, platform_runs)
    for w in platform_runs.values():
        state = "loaded" if w.get("loaded") else "idle"
        rows.append([text("platform_row"), state, "",
                     text("platform_lateness", p50=w["late_us_p50"] / 1e3, p99=w["late_us_p99"] / 1e3,
                          max=w["late_us_max"] / 1e3), "", "", "", "", ""])
    out += ["", table(["set-up", "load", "rate (Hz)", "period p50 / p99 / max (ms)",
                       "device to force p50 / p99 / max (ms)", "CPU (cores)",
                       "stiffness error, median / worst cycle", "jitter, median / worst window (mN)",
                       "resident (MB)"], rows), ""]
    out += [_histograms(ctx, runs), ""]
    return out


def _targets(ctx, text, runs, platform_runs):
    """Each set-up's targets: one 60 s run per set-up, no spread but the run's own; the period max
    beside the platform's wake-up max of the same run and load, the heavy scene's period p99
    against the platform's floor (1 ms plus its wake-up lateness p99)."""
    for target in ctx.targets.in_section("haptic"):
        chosen = target.records(runs)
        if not chosen:
            continue
        record = chosen[0]
        run = text("run", seconds=record["seconds"])
        value = value_at(record, target.key)
        if target.comparison == "reported":
            ctx.targets.checked(target, value, run, "")
        elif target.comparison == "within":
            drift = abs(value - target.goal) / target.goal
            verdict = "met" if target.met(value) else text("rate_missed", excess=100 * (drift - target.tolerance / 100))
            ctx.targets.checked(target, value, run, verdict)
        elif target.also is None:
            ctx.targets.measured(target, Measure(value / 1e3, how=run))
        else:
            select = target.also.get("select") or {}
            wakeup = next((w for w in platform_runs.values() if target.matches(w, select)), None)
            late = None if wakeup is None else value_at(wakeup, target.also["key"]) / 1e3
            if target.params.get("over_platform_floor"):
                if late is None:
                    continue
                # The platform's floor: the period an empty SCHED_FIFO thread keeps is 1 ms plus
                # its lateness p99.
                over = value / 1e3 - (1.0 + late)
                ctx.targets.checked(target, over, text("runs_each", seconds=record["seconds"]),
                                    target.excess_verdict(over))
            else:
                how = run if late is None else text("wakeup", run=run, late_ms=late)
                ctx.targets.measured(target, Measure(value / 1e3, how=how))


def _histograms(ctx, runs):
    """The period and the latency (20 us bins, counts on a log axis) of the loaded runs."""
    figure_runs = [r for r in runs if r["loaded"]]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    bins = [20 * i for i in range(len(figure_runs[0]["period_hist"]))] if figure_runs else []
    for r in figure_runs:
        for axis, key in zip(axes, ("period_hist", "latency_hist")):
            counts = [max(c, 0.5) for c in r[key]]
            axis.step([b / 1e3 for b in bins], counts, where="post", label=r["setup"])
    axes[0].set_xlabel("period (ms; last bin: 4 ms and more)")
    axes[1].set_xlabel("device to force (ms; last bin: 4 ms and more)")
    for axis in axes:
        axis.set_yscale("log")
        axis.set_ylabel("ticks")
        axis.grid(True, which="both", alpha=0.3)
        axis.set_ylim(bottom=0.8)
    axes[1].legend(fontsize=8)
    fig.suptitle("haptic loop under load (busy cores, recording, rviz)")
    return ctx.figures.save("haptic_loop_histograms.png")
