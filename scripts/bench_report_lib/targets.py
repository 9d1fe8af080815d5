"""bench/targets.yaml: every target the report checks, read and checked here, and the report's
Targets table made from it (in the file's order) with what the sections measured.

A target names what it reads (a raw file and a benchmark, or a JSON key of the records it
selects); its goal, unit and comparison are data, never code. `load` refuses a file with a
missing or malformed field, naming the target and the file; `check_raw` refuses a target whose
benchmark, counter, record or key is not in the raw results."""
import fnmatch
import os

import yaml

from . import common

COMPARISONS = ("<=", ">=", "==", "within", "reported")
REQUIRED = ("id", "section", "name", "comparison", "unit", "format", "measures", "file")
# Fields of a target that reads a Google Benchmark file (.json) and of one that reads JSON
# lines (.jsonl); either may have the common ones.
BENCHMARK_FIELDS = ("benchmark", "over", "counter", "per", "per_step", "worst")
RECORD_FIELDS = ("key", "select", "also")
COMMON_FIELDS = REQUIRED + ("goal", "tolerance", "goal_text", "spread", "params")
# The unit a time is shown in, per ns.
TIME_SCALE = {"ns": 1.0, "us": 1e-3, "ms": 1e-6, "s": 1e-9}


class TargetsError(Exception):
    """A bad bench/targets.yaml, or a target that reads what the raw results do not have."""


def _shown(number):
    """A goal or parameter as written: numbers by "g", strings (YAML's -1e-4) as they are."""
    return number if isinstance(number, str) else format(number, "g")


class Target:
    """One entry of bench/targets.yaml (see its header for the fields)."""

    def __init__(self, spec, source):
        self.source = source
        self.id = spec["id"]
        self.section = spec["section"]
        self.name = spec["name"]
        self.comparison = spec["comparison"]
        self.unit = spec["unit"]
        self.format = spec["format"]
        self.measures = spec["measures"]
        self.file = spec["file"]
        self.goal_written = spec.get("goal")
        self.goal = None if self.goal_written is None else float(self.goal_written)
        self.tolerance = spec.get("tolerance")
        self.goal_text = spec.get("goal_text")
        self.spread = spec.get("spread")
        self.params = spec.get("params") or {}
        self.benchmark = spec.get("benchmark")
        self.over = spec.get("over")
        self.counter = spec.get("counter")
        self.per = spec.get("per")
        self.per_step = bool(spec.get("per_step", False))
        self.worst = bool(spec.get("worst", False))
        self.key = spec.get("key")
        self.select = spec.get("select") or {}
        self.also = spec.get("also")

    def error(self, message):
        return TargetsError(f"{self.source}: target '{self.id}': {message}")

    # --- what the table shows ---------------------------------------------------------------
    def goal_column(self):
        if self.comparison == "reported":
            return "(reported)"
        if self.goal_text is not None:
            template = self.goal_text
        elif self.comparison == "within":
            template = "{goal} {unit} +- {tolerance} %"
        else:
            template = "{comparison} {goal}" + (" {unit}" if self.unit else "")
        fields = {name: _shown(value) for name, value in self.params.items()}
        fields.update(goal=_shown(self.goal_written) if self.goal_written is not None else "",
                      unit=self.unit, comparison=self.comparison,
                      tolerance=_shown(self.tolerance) if self.tolerance is not None else "")
        try:
            return template.format(**fields)
        except (KeyError, IndexError, ValueError) as error:
            raise self.error(f"goal_text '{template}' names a field it does not have ({error})") from None

    def number(self):
        """The value's format as a str.format template, "{:.2f}"."""
        return "{:" + self.format + "}"

    def shown(self, value):
        """The value in its format and unit, "3.70 us"."""
        return self.number().format(value) + (f" {self.unit}" if self.unit else "")

    def title(self, fill):
        try:
            return self.name.format(**fill)
        except (KeyError, IndexError, ValueError) as error:
            raise self.error(f"name '{self.name}' names a field the report does not fill ({error})") from None

    # --- the check ----------------------------------------------------------------------------
    def met(self, value):
        if self.comparison == "<=":
            return value <= self.goal
        if self.comparison == ">=":
            return value >= self.goal
        if self.comparison == "==":
            return value == self.goal
        if self.comparison == "within":
            return abs(value - self.goal) / abs(self.goal) <= self.tolerance / 100.0
        raise self.error("a reported figure has no goal to meet")

    def excess_verdict(self, value):
        """met, or by how much the value is past the goal, in its unit (points for a %)."""
        if self.met(value):
            return "met"
        unit = "points" if self.unit == "%" else self.unit
        excess = ("{:" + self.format.lstrip("+- ") + "}").format(abs(value - self.goal))
        return f"missed by {excess}" + (f" {unit}" if unit else "")

    def share_verdict(self, value):
        """met, or the share reached against the share asked for ("missed: 65 % of 95 %")."""
        if self.met(value):
            return "met"
        return f"missed: {self.shown(value)} of {_shown(self.goal_written)}" + (f" {self.unit}" if self.unit else "")

    def plain_verdict(self, value, note=None):
        """met or missed (with a note on what was met)."""
        if self.met(value):
            return "met"
        return "missed" + (f" ({note})" if note else "")

    # --- the records it reads -----------------------------------------------------------------
    def matches(self, record, select=None):
        return all(record.get(field) == value for field, value in (self.select if select is None else select).items())

    def records(self, records):
        return [record for record in records if self.matches(record)]

    def keys(self):
        return [self.key] if isinstance(self.key, str) else list(self.key or [])


def value_at(record, path):
    """record["a"]["b"] for the path "a.b"; KeyError when absent."""
    value = record
    for part in path.split("."):
        value = value[part]
    return value


class Targets:
    """The targets of bench/targets.yaml in its order, and the Targets table's rows the sections
    fill in (a target whose raw file is absent has no row)."""

    def __init__(self, targets, source):
        self.source = source
        self.targets = targets
        self.by_id = {target.id: target for target in targets}
        self.rows = {}

    def get(self, target_id):
        if target_id not in self.by_id:
            raise TargetsError(f"{self.source}: no target '{target_id}' (the report measures it)")
        return self.by_id[target_id]

    def in_section(self, section):
        return [target for target in self.targets if target.section == section]

    def measured(self, target, measure, **fill):
        """A row for a Measure: its median, its spread, and against a `<=` goal met, missed by
        how much, or within noise."""
        verdict = "" if target.comparison == "reported" else measure.verdict(target.goal)
        self.rows[target.id] = [target.title(fill), target.goal_column(), target.shown(measure.median),
                                measure.spread(target.number()), verdict]

    def checked(self, target, value, spread, verdict, detail=None, measured=None, **fill):
        """A row for a single value (or a text for it, `measured`) with its spread and verdict."""
        shown = measured if measured is not None else target.shown(value) + (f" {detail}" if detail else "")
        self.rows[target.id] = [target.title(fill), target.goal_column(), shown, spread, verdict]

    def table_rows(self):
        return [self.rows[target.id] for target in self.targets if target.id in self.rows]


def _check_spec(spec, index, source, sections):
    label = f"target '{spec['id']}'" if isinstance(spec, dict) and "id" in spec else f"target #{index + 1}"
    if not isinstance(spec, dict):
        raise TargetsError(f"{source}: {label}: not a mapping of fields")

    def fail(message):
        return TargetsError(f"{source}: {label}: {message}")

    for field in REQUIRED:
        if field not in spec:
            raise fail(f"no {field}")
    unknown = [field for field in spec if field not in COMMON_FIELDS + BENCHMARK_FIELDS + RECORD_FIELDS]
    if unknown:
        raise fail(f"unknown field(s) {', '.join(unknown)}")
    if sections is not None and spec["section"] not in sections:
        raise fail(f"section '{spec['section']}' is none of the report's ({', '.join(sections)})")
    comparison = spec["comparison"]
    if comparison not in COMPARISONS:
        raise fail(f"comparison '{comparison}' is none of {', '.join(COMPARISONS)}")
    if comparison == "reported":
        if "goal" in spec:
            raise fail("a reported figure has no goal")
    else:
        if spec.get("goal") is None:
            raise fail("no goal")
        try:
            float(spec["goal"])
        except (TypeError, ValueError):
            raise fail(f"goal '{spec['goal']}' is not a number") from None
    if (comparison == "within") != ("tolerance" in spec):
        raise fail("a tolerance (%) goes with comparison 'within', and only with it")
    if not isinstance(spec["unit"], str):
        raise fail("unit is not a text (write \"\" for none)")
    try:
        format(1.0, spec["format"])
    except (TypeError, ValueError):
        raise fail(f"format '{spec['format']}' is not a number format (.2f, +.3g)") from None
    file = spec["file"]
    if file.endswith(".json"):
        if "benchmark" not in spec:
            raise fail(f"no benchmark (it reads {file}, a Google Benchmark file)")
        extra = [field for field in RECORD_FIELDS if field in spec]
        if comparison not in ("<=", "reported"):
            raise fail("a benchmark's target is checked as `<=` (or reported)")
    elif file.endswith(".jsonl"):
        if "key" not in spec:
            raise fail(f"no key (it reads {file}, JSON lines)")
        extra = [field for field in BENCHMARK_FIELDS if field in spec]
    else:
        raise fail(f"file '{file}' is neither a .json nor a .jsonl raw file")
    if extra:
        raise fail(f"field(s) {', '.join(extra)} do not apply to {file}")
    for field in ("select", "params"):
        if field in spec and not isinstance(spec[field], dict):
            raise fail(f"{field} is not a mapping")
    keys = spec.get("key")
    if keys is not None and not (isinstance(keys, str) or (isinstance(keys, list) and keys
                                                           and all(isinstance(k, str) for k in keys))):
        raise fail("key is a field name (a.b inside a field) or a list of them")
    also = spec.get("also")
    if also is not None and (not isinstance(also, dict) or "file" not in also or "key" not in also
                             or any(field not in ("file", "key", "select") for field in also)):
        raise fail("also is a mapping of file, key and (optionally) select")
    if spec.get("per_step") and "counter" in spec:
        raise fail("per_step is a time's, not a counter's")
    if spec.get("spread") not in (None, "deterministic") and file.endswith(".json"):
        raise fail("a benchmark's spread is its repetitions', or 'deterministic'")


def load(path, sections=None, source=None):
    """The targets of a targets.yaml; TargetsError naming the target and the file on any fault."""
    source = source or path
    try:
        with open(path) as handle:
            specs = yaml.safe_load(handle)
    except OSError as error:
        raise TargetsError(f"{source}: cannot read it ({error.strerror})") from None
    except yaml.YAMLError as error:
        raise TargetsError(f"{source}: not YAML: {error}") from None
    if not isinstance(specs, list):
        raise TargetsError(f"{source}: not a list of targets")
    targets = []
    for index, spec in enumerate(specs):
        _check_spec(spec, index, source, sections)
        if any(target.id == spec["id"] for target in targets):
            raise TargetsError(f"{source}: target '{spec['id']}' twice")
        target = Target(spec, source)
        target.goal_column()  # its goal_text's fields
        targets.append(target)
    return Targets(targets, source)


def _shown_path(path):
    """The raw file's path as the error shows it: from the current folder when under it."""
    relative = os.path.relpath(path)
    return path if relative.startswith("..") else relative


def _check_benchmark(target, path, names, entries, name):
    matching = fnmatch.filter(names, name) if "*" in name else [name] if name in names else []
    if not matching:
        raise target.error(f"reads benchmark '{name}', which {_shown_path(path)} does not have")
    for counter in (target.counter, target.per):
        if counter and not any(counter in entry for entry in entries if common.benchmark_name(entry) in matching):
            raise target.error(f"reads counter '{counter}' of '{name}', which {_shown_path(path)} does not have")


def _check_records(target, path, select, keys):
    records = [record for record in common.load_jsonl(path) if target.matches(record, select)]
    if not records:
        raise target.error(f"selects {select}, which no record of {_shown_path(path)} has")
    for key in keys:
        try:
            value_at(records[0], key)
        except (KeyError, TypeError):
            raise target.error(f"reads key '{key}', which {_shown_path(path)}'s records do not have") from None


def check_raw(targets, raw, section=None):
    """Each target (of `section`, or all) whose raw file is in `raw` reads a benchmark (and
    counter), or selects records with the key, that the file has: TargetsError naming the target
    and the file otherwise."""
    for target in targets.targets if section is None else targets.in_section(section):
        path = os.path.join(raw, target.file)
        if not os.path.exists(path):
            continue
        if target.file.endswith(".json"):
            entries = common.load_json(path)["benchmarks"]
            names = common.benchmark_names(path)
            for name in (target.benchmark, target.over):
                if name:
                    _check_benchmark(target, path, names, entries, name)
        else:
            _check_records(target, path, target.select, target.keys())
            if target.also:
                also = os.path.join(raw, target.also["file"])
                if os.path.exists(also):
                    keys = target.also["key"]
                    _check_records(target, also, target.also.get("select") or {},
                                   [keys] if isinstance(keys, str) else keys)
