"""The targets that read a Google Benchmark file, measured alike from their fields in
bench/targets.yaml: a benchmark's time (per step, per counter, in the target's unit), a counter,
the worst of a family, or the ratio of two (paired repetition by repetition)."""
import fnmatch
import os

from . import common
from .targets import TIME_SCALE


def _names(pattern, available):
    return fnmatch.filter(available, pattern) if "*" in pattern else [pattern] if pattern in available else []


def _measure(target, path):
    """The target's Measure, or None when the file lacks what it reads."""
    if target.counter and target.spread == "deterministic":
        # A deterministic counter: the median run's value, no spread.
        results = common.load_benchmarks(path)
        values = {name: counters[target.counter] for name, (_, counters, _) in results.items()
                  if target.counter in counters}
        picked = [values[name] for name in _names(target.benchmark, list(values))]
        if not picked:
            return None
        value = max(picked)
        if target.over:
            if target.over not in values:
                return None
            value = value / values[target.over]
        return common.Measure(value, how="deterministic")
    if target.counter:
        measures = common.counter_measures(path, target.counter)
    else:
        measures = common.load_measures(path, per_step=target.per_step)
    picked = [measures[name] for name in _names(target.benchmark, list(measures))]
    if not picked:
        return None
    measure = max(picked, key=lambda m: m.median)
    if target.over:
        if target.over not in measures:
            return None
        return measure.ratio(measures[target.over])
    if not target.counter:
        measure = measure.scaled(TIME_SCALE.get(target.unit, 1.0))
    return measure


def measure_section(ctx, section):
    """Records a row for each target of `section` that reads a Google Benchmark file present in
    the raw results (a time per counter only where that counter is above 0)."""
    for target in ctx.targets.in_section(section):
        if not target.benchmark:
            continue
        path = os.path.join(ctx.raw, target.file)
        if not os.path.exists(path):
            continue
        measure = _measure(target, path)
        if measure is None:
            continue
        fill = {}
        if target.per:
            results = common.load_benchmarks(path)
            count = results[target.benchmark][1].get(target.per, 0.0) if target.benchmark in results else 0.0
            if count <= 0:
                continue
            measure = measure.scaled(1.0 / count)
            fill[target.per] = count
        ctx.targets.measured(target, measure, **fill)
