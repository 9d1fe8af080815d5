"""What a section is given: the raw results' folder, the targets, the benchmark names of
bench/benchmarks.yaml, the figures' folder and its prose."""
import os

import yaml

PROSE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "prose")


class ReportError(Exception):
    """A data file of the report (bench/benchmarks.yaml, a prose file) lacks what the code asks."""


class Prose:
    """A section's prose (prose/SECTION.yaml): str.format templates by key."""

    def __init__(self, section):
        self.path = os.path.join(PROSE, section + ".yaml")
        with open(self.path) as handle:
            self.texts = yaml.safe_load(handle) or {}

    def __call__(self, key, **fields):
        if key not in self.texts:
            raise ReportError(f"{self.path}: no text '{key}'")
        try:
            return self.texts[key].format(**fields)
        except (KeyError, IndexError, ValueError) as error:
            raise ReportError(f"{self.path}: text '{key}' names a field the report does not give ({error})") from None


class Names(dict):
    """bench/benchmarks.yaml's entry for one raw file: a missing name is an error naming both."""

    def __init__(self, values, source, file):
        super().__init__(values)
        self.where = f"{source} ({file})"

    def __missing__(self, key):
        raise ReportError(f"{self.where}: no '{key}'")


class Context:
    def __init__(self, raw, targets, benchmarks_path, figures, source="bench/benchmarks.yaml"):
        self.raw = raw
        self.targets = targets
        self.figures = figures
        self.source = source
        with open(benchmarks_path) as handle:
            self.benchmarks = yaml.safe_load(handle)

    def path(self, file):
        return os.path.join(self.raw, file)

    def has(self, file):
        return os.path.exists(self.path(file))

    def names(self, file):
        if file not in self.benchmarks:
            raise ReportError(f"{self.source}: no entry for {file}")
        return Names(self.benchmarks[file], self.source, file)

    def prose(self, section):
        return Prose(section)
