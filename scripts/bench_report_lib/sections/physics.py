"""## 3. Physics step (physics_step.json): every scenario and model, the solver's work, and the
step against interfaces and objects."""
from .. import benchmark_targets
from ..common import load_benchmarks, table

FILE = "physics_step.json"


def section(ctx):
    names = ctx.names(FILE)
    text = ctx.prose("physics")
    results = load_benchmarks(ctx.path(FILE))
    models = names["models"]
    out = [text("heading"), "", text("command")]
    per_step = {name: time_ns / 1e3 / counters["steps"] for name, (time_ns, counters, _) in results.items()}
    ratios = [(models.index(a), models.index(b)) for a, b in names["ratio_columns"]]
    rows = []
    for s, scenario in enumerate(names["scenarios"]):
        values = [per_step.get(names["scenario_step"].format(scenario=s, model=m), float("nan"))
                  for m in range(len(models))]
        rows.append([scenario] + [f"{value:.1f}" for value in values] +
                    [f"{values[a] / values[b]:.2f}" for a, b in ratios])
    out += [text("models"), ""]
    out += ["", table(["scenario"] + [f"{m} (us/step)" for m in models] +
                      [f"{models[a]} / {models[b]}" for a, b in ratios], rows), ""]
    # The solver's work behind those times (the bench's counters: mean per step of the run).
    rows = []
    for s, scenario in enumerate(names["scenarios"]):
        row = [scenario]
        for m in range(len(models)):
            counters = results.get(names["scenario_step"].format(scenario=s, model=m), (0, {}, ""))[1]
            row.append(f"{counters['iterations']:.1f} / {counters['rows']:.1f}"
                       if "iterations" in counters and "rows" in counters else "")
        rows.append(row)
    out += [text("iterations"), "", table(["scenario"] + models, rows), ""]
    benchmark_targets.measure_section(ctx, "physics")
    for sweep in names["sweeps"]:
        rows = []
        for count in sweep["counts"]:
            rows.append([count] + [f"{per_step.get(sweep['benchmark'].format(count=count, model=m), float('nan')):.1f}"
                                   for m in range(len(models))])
        out += [text("against", label=sweep["label"]), "",
                table([sweep["column"]] + [f"{m} (us/step)" for m in models], rows), ""]
    return out
