"""## 12. Soft bodies: the step against node count (soft_body.json), the press against
Boussinesq's w0 (soft_fidelity.jsonl), the servo loop pressing a soft block (soft_loop.jsonl)."""
from .. import benchmark_targets
from ..common import load_benchmarks, load_json, load_jsonl, table
from ..targets import value_at

STEPS = "soft_body.json"
FIDELITY = "soft_fidelity.jsonl"
LOOP = "soft_loop.jsonl"


def section(ctx):
    if not ctx.has(STEPS) and not ctx.has(FIDELITY):
        return []
    text = ctx.prose("soft")
    out = [text("heading"), "", text("intro"), ""]
    if ctx.has(STEPS):
        out += _steps(ctx, text)
    if ctx.has(FIDELITY):
        out += _fidelity(ctx, text)
    if ctx.has(LOOP):
        out += _loop(ctx, text)
    return out


def _measured_at(text, commit):
    return text("measured_at", commit=commit) if commit else ""


def _steps(ctx, text):
    names = ctx.names(STEPS)
    results = load_benchmarks(ctx.path(STEPS))
    commit = load_json(ctx.path(STEPS)).get("context", {}).get("commit")
    out = [text("steps", measured_at=_measured_at(text, commit)), ""]
    rows = []
    for nodes in names["nodes"]:
        for fingers in names["fingers"]:
            entry = results.get(names["step"].format(nodes=nodes, fingers=fingers))
            if not entry:
                continue
            counters = entry[1]
            rows.append([f"{counters['nodes']:.0f}", str(fingers), f"{counters['p50_us']:.0f}",
                         f"{counters['p99_us']:.0f}", f"{counters['factor_nnz'] / 1e6:.2f}",
                         f"{counters['setup_s']:.2f}"])
    out += [table(["nodes", "pads", "step p50 (us)", "p99 (us)", "factor nonzeros (M)", "factoring (s)"], rows), ""]
    benchmark_targets.measure_section(ctx, "soft")
    return out


def _fidelity(ctx, text):
    runs = load_jsonl(ctx.path(FIDELITY))
    out = [text("fidelity"), ""]
    rows = []
    for run in runs:
        rows.append([str(run["nodes"]), f"{run['step_p50_us']:.0f}", f"{run['pad_centre'] * 1e3:.3f}",
                     f"{run['pad_centre'] / run['boussinesq']:.3f}", f"{run['point_centre'] * 1e3:.3f}",
                     f"{run['point_centre'] / run['boussinesq']:.2f}",
                     f"{abs(run['plate_shortening'] / run['plate_expected'] - 1):.1e}"])
    out += [table(["nodes", "step p50 (us)", "pad sink (mm)", "pad / w0", "point sink (mm)", "point / w0",
                   "plate error"], rows), ""]
    if runs:
        out += [text("w0", w0_mm=runs[0]["boussinesq"] * 1e3), ""]
    for target in ctx.targets.in_section("soft"):
        if target.file != FIDELITY:
            continue
        # The finest mesh whose step fits the budget (1 kHz): its pad's sink against w0.
        within = [run for run in target.records(runs) if run["step_p50_us"] <= target.params["budget_us"]]
        if within:
            finest = max(within, key=lambda run: run["nodes"])
            error = 100 * abs(finest["pad_centre"] / finest["boussinesq"] - 1.0)
            ctx.targets.checked(target, error, target.spread, target.excess_verdict(error), nodes=finest["nodes"])
    return out


def _loop(ctx, text):
    runs = load_jsonl(ctx.path(LOOP))
    for run in runs:
        run.setdefault("exchange", ctx.names(LOOP)["default_exchange"])
    commit = runs[0].get("commit") if runs else None
    out = [text("loop", measured_at=_measured_at(text, commit)), ""]
    rows = []
    for run in runs:
        rows.append([str(run["nodes"]), run["exchange"], f"{run['loadavg_1min']:.2f}",
                     f"{run['step_us_p50']:.0f} / {run['step_us_p99']:.0f}",
                     f"{run['physics_steps_per_s']:.0f}", f"{100.0 * run['stale_ticks'] / max(1, run['ticks']):.1f} %",
                     f"{run['floor_us_p99']:.1f}", f"{run['period_us_p50']:.1f} / {run['period_us_p99']:.1f}",
                     f"{run['p99_over_floor_us']:+.1f}",
                     f"{run['latency_us_p50']:.0f} / {run['latency_us_p99']:.0f}"])
    out += [table(["nodes", "exchange", "load", "step p50 / p99 (us)", "physics steps/s", "stale ticks",
                   "floor p99 (us)", "period p50 / p99 (us)", "period p99 - floor p99 (us)",
                   "device to force p50 / p99 (us)"], rows), ""]
    for target in ctx.targets.in_section("soft"):
        chosen = target.records(runs) if target.file == LOOP else []
        if not chosen:
            continue
        # Every size must meet it: the worst of the runs.
        worst = max(value_at(run, target.key) for run in chosen)
        ctx.targets.checked(target, worst, target.spread, target.plain_verdict(worst),
                            detail=text("worst_of", count=len(chosen), of=target.params["of"]))
    return out
