"""What every section shares: reading the raw files (Google Benchmark JSON, JSON lines), a
measure with its spread and its ratios, medians and percentiles, Markdown tables and figures."""
import json
import math
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# Google Benchmark's time units, in ns.
NS_PER = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}


def load_json(path):
    with open(path) as handle:
        return json.load(handle)


def load_jsonl(path):
    """The records of a JSON-lines file, blank lines skipped."""
    with open(path) as handle:
        return [json.loads(line) for line in handle if line.strip()]


def load_text(path):
    with open(path) as handle:
        return handle.read()


def benchmark_name(entry):
    """"BM_X/a:1/iterations:1/repeats:3/real_time" -> "BM_X/a:1": the arguments only."""
    return "/".join(part for part in entry.get("run_name", entry["name"]).split("/")
                    if not part.startswith(("iterations:", "repeats:", "min_time:"))
                    and part not in ("real_time", "manual_time"))


def benchmark_names(path):
    """Every benchmark name a Google Benchmark file holds, in its order."""
    names = []
    for entry in load_json(path)["benchmarks"]:
        name = benchmark_name(entry)
        if name not in names:
            names.append(name)
    return names


def arg(name, key):
    """The integer argument `key` of a benchmark name ("BM_X/mesh:6" -> 6), or None."""
    for part in name.split("/"):
        if part.startswith(key + ":"):
            return int(part.split(":")[1])
    return None


def load_benchmarks(path):
    """name -> (median real time in ns, counters, label) for repeated runs; plain runs taken as
    they are."""
    result = {}
    for entry in load_json(path)["benchmarks"]:
        if entry.get("run_type") == "aggregate" and entry.get("aggregate_name") != "median":
            continue
        name = benchmark_name(entry)
        time_ns = entry["real_time"] * NS_PER[entry.get("time_unit", "ns")]
        counters = {k: v for k, v in entry.items() if isinstance(v, (int, float))}
        if entry.get("run_type") == "aggregate" or name not in result:
            result[name] = (time_ns, counters, entry.get("label", ""))
    return result


class Measure:
    """A median and its spread: the range of the repetitions (or rounds), or median +- the
    standard deviation where a run kept only aggregates, or a single value (one run)."""

    def __init__(self, median, low=None, high=None, how="one run"):
        self.median = median
        self.low = median if low is None else low
        self.high = median if high is None else high
        self.how = how
        self.values = None  # every repetition's value, when known (paired ratios)

    def scaled(self, factor):
        result = Measure(self.median * factor, self.low * factor, self.high * factor, self.how)
        result.values = None if self.values is None else [v * factor for v in self.values]
        return result

    def ratio(self, other):
        """self / other; paired repetition by repetition when both have the same count, else the
        widest ratio their spreads allow."""
        median = self.median / other.median
        if self.values and other.values and len(self.values) == len(other.values):
            ratios = [a / b for a, b in zip(self.values, other.values)]
            result = Measure(median, min(ratios), max(ratios), f"{len(ratios)} paired repetitions")
            result.values = ratios
            return result
        if self.how == "one run" and other.how == "one run":
            return Measure(median)
        how = self.how if self.how == other.how else f"{self.how} / {other.how}"
        return Measure(median, self.low / other.high, self.high / other.low, how)

    def spread(self, fmt):
        if self.low == self.high:
            return self.how
        return f"{fmt.format(self.low)}-{fmt.format(self.high)} ({self.how})"

    def verdict(self, limit):
        """For a goal `value <= limit`: met, missed by how much, or within noise when the spread
        straddles the goal."""
        if self.high <= limit:
            return "met"
        if self.low > limit:
            if self.low == self.high:
                return f"missed by {self.low / limit:.2f}x"
            return f"missed by {self.low / limit:.2f}-{self.high / limit:.2f}x"
        if self.median <= limit:
            return f"within noise (median met; up to {self.high / limit:.2f}x)"
        return f"within noise (median missed by {self.median / limit:.2f}x; down to {self.low / limit:.2f}x)"


def load_measures(path, per_step=False):
    """name -> Measure of the real time in ns (per step with per_step), from the repetitions when
    the file has them, else from the median and standard deviation aggregates."""
    data = load_json(path)
    median, stddev, values = {}, {}, {}
    for entry in data["benchmarks"]:
        name = benchmark_name(entry)
        time_ns = entry["real_time"] * NS_PER[entry.get("time_unit", "ns")]
        if per_step:
            steps = entry.get("steps", 0.0)
            if entry.get("aggregate_name") != "stddev":
                time_ns = time_ns / steps if steps else float("nan")
        if entry.get("run_type") == "aggregate":
            if entry.get("aggregate_name") == "median":
                median[name] = time_ns
            elif entry.get("aggregate_name") == "stddev":
                stddev[name] = (time_ns, entry)
        else:
            values.setdefault(name, []).append(time_ns)
    result = {}
    for name in set(median) | set(values):
        reps = values.get(name, [])
        if name not in median:
            median[name] = sorted(reps)[len(reps) // 2]
        if len(reps) > 1:
            result[name] = Measure(median[name], min(reps), max(reps), f"{len(reps)} repetitions")
            result[name].values = reps
        elif name in stddev:
            sd, entry = stddev[name]
            if per_step:
                # The aggregate's steps is the steps' standard deviation (0); the median's count.
                sd = sd / (_median_steps(data, name) or float("nan"))
            result[name] = Measure(median[name], median[name] - sd, median[name] + sd,
                                   f"median +- sd of {entry.get('repetitions', '?')}")
        else:
            result[name] = Measure(median[name])
    return result


def _median_steps(data, name):
    for entry in data["benchmarks"]:
        if benchmark_name(entry) == name and entry.get("aggregate_name") == "median":
            return entry.get("steps")
    return None


def repetitions(path, counter):
    """name -> the counter's value in each repetition (not the aggregates), for the spread."""
    values = {}
    for entry in load_json(path)["benchmarks"]:
        if entry.get("run_type") == "aggregate" or counter not in entry:
            continue
        values.setdefault(benchmark_name(entry), []).append(entry[counter])
    return values


def counter_measures(path, counter):
    """name -> Measure of a counter: its median and the range of the repetitions, or median +- the
    standard deviation aggregate where the file kept only aggregates, or its one value."""
    median, stddev = {}, {}
    for entry in load_json(path)["benchmarks"]:
        if entry.get("aggregate_name") == "median" and counter in entry:
            median[benchmark_name(entry)] = entry[counter]
        if entry.get("aggregate_name") == "stddev" and counter in entry:
            stddev[benchmark_name(entry)] = (entry[counter], entry.get("repetitions", "?"))
    result = {}
    for name, values in repetitions(path, counter).items():
        value = median.get(name, sorted(values)[len(values) // 2])
        if len(values) > 1:
            result[name] = Measure(value, min(values), max(values), f"{len(values)} repetitions")
            result[name].values = values
        else:
            result[name] = Measure(value)
    for name, value in median.items():
        if name not in result:
            if name in stddev:
                sd, count = stddev[name]
                result[name] = Measure(value, value - sd, value + sd, f"median +- sd of {count}")
            else:
                result[name] = Measure(value)
    return result


def percentile(values, q):
    """The q-quantile (0..1) of the values, linearly interpolated; nan when there are none."""
    ordered = sorted(values)
    if not ordered:
        return float("nan")
    position = (len(ordered) - 1) * q
    low = math.floor(position)
    high = min(low + 1, len(ordered) - 1)
    return ordered[low] + (ordered[high] - ordered[low]) * (position - low)


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


class Figures:
    """Saves the current matplotlib figure into a folder and links it from the report."""

    def __init__(self, folder):
        self.folder = folder
        os.makedirs(folder, exist_ok=True)

    def save(self, name):
        plt.tight_layout()
        plt.savefig(os.path.join(self.folder, name), dpi=110)
        plt.close()
        return f"![{name}](figures/{name})"


def match(pattern, name):
    """The integer fields of a benchmark-name pattern ("BM_X/mesh:{mesh}") in `name`, or None
    when the name is not one of the pattern's."""
    parts = re.split(r"\{(\w+)\}", pattern)
    regex = "".join(re.escape(part) if i % 2 == 0 else f"(?P<{part}>-?\\d+)" for i, part in enumerate(parts))
    found = re.fullmatch(regex, name)
    return None if found is None else {key: int(value) for key, value in found.groupdict().items()}
