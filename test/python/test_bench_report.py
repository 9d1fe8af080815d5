"""scripts/bench_report: bench/REPORT.md (and bench/SCALE.md) made again from the committed raw
results is the committed file byte for byte, as readme_figures_test checks the docs' blocks; its
Targets table is bench/targets.yaml's; a bad targets.yaml, or a target that reads what the raw
results lack, is refused naming the target and the file. Nothing here needs a build: the report
reads only committed files."""
import os
import re
import subprocess
import sys

import pytest
import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))

from bench_report_lib import report, targets  # noqa: E402
from bench_report_lib.sections import contact  # noqa: E402
from bench_report_lib.targets import TargetsError  # noqa: E402

RAW = os.path.join(ROOT, "bench", "raw", "full")
TARGETS = os.path.join(ROOT, "bench", "targets.yaml")


def committed(name):
    with open(os.path.join(ROOT, "bench", name)) as handle:
        return handle.read()


def test_the_report_is_what_its_raw_results_make():
    run = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "bench_report"), "--check", RAW],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stdout + run.stderr
    assert "bench/REPORT.md is what" in run.stdout


def test_the_scale_report_is_what_its_raw_results_make(tmp_path):
    assert report.write_scale(os.path.join(ROOT, "bench", "raw", "scale"), str(tmp_path)) == 0
    assert (tmp_path / "SCALE.md").read_text() == committed("SCALE.md")


def test_every_figure_linked_is_there_and_every_figure_there_is_linked():
    linked = set()
    for name in ("REPORT.md", "SCALE.md"):
        linked |= set(re.findall(r"\]\(figures/([^)]+)\)", committed(name)))
    assert linked == set(os.listdir(os.path.join(ROOT, "bench", "figures")))


def table_rows(text, heading):
    """The rows (lists of cells) of the first table after `heading`."""
    lines = text[text.index(heading + "\n"):].splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("|"))
    rows = []
    for line in lines[start + 2:]:
        if not line.startswith("|"):
            break
        rows.append([cell.strip() for cell in line.strip("|").split(" | ")])
    return rows


def test_the_targets_table_is_targets_yaml_in_its_order():
    loaded = report.load_targets()
    rows = table_rows(committed("REPORT.md"), "## Targets")
    # The committed raw results have every raw file: every target has its row.
    assert len(rows) == len(loaded.targets)
    for row, target in zip(rows, loaded.targets):
        name = re.escape(target.name.strip())
        name = re.sub(r"\\\{[^}]*\\\}", ".+", name)
        assert re.fullmatch(name, row[0]), (target.id, row[0])
        assert row[1] == target.goal_column(), target.id
        assert row[4] != "" or target.comparison == "reported", target.id


def test_a_goal_changed_in_targets_yaml_changes_the_report(tmp_path):
    specs = yaml.safe_load(open(TARGETS))
    for spec in specs:
        if spec["id"] == "contact.area_plate":
            spec["goal"] = 4
    path = tmp_path / "targets.yaml"
    path.write_text(yaml.safe_dump(specs))
    ctx = report._context(RAW, str(tmp_path), str(path))
    contact.section(ctx)
    assert ctx.targets.rows["contact.area_plate"] == [
        "one contact area (no location), n_SGO = 8, 100,352-triangle plate (2 mm cells)", "<= 4 us", "3.70 us",
        "3.09-4.25 (3 repetitions)", "within noise (median met; up to 1.06x)"]


def test_the_code_holds_no_goal_and_no_benchmark_name():
    package = os.path.join(ROOT, "scripts", "bench_report_lib")
    for folder, _, files in os.walk(package):
        for name in files:
            if not name.endswith(".py"):
                continue
            code = open(os.path.join(folder, name)).read()
            assert not re.search(r"BM_[A-Za-z]{2,}", code), name  # BM_X: a docstring's example
            assert not re.search(r"[\"'](<=|>=) ?[-\d]", code), name
    assert not re.search(r"BM_[A-Za-z]{2,}", open(os.path.join(ROOT, "scripts", "bench_report")).read())


# --- the loader -----------------------------------------------------------------------------------

GOOD = {"id": "contact.plate", "section": "contact", "name": "one contact area", "goal": 2, "unit": "us",
        "comparison": "<=", "format": ".2f", "measures": "The time of one contact area.",
        "file": "contact_area.json", "benchmark": "BM_ContactAreaOnly/mesh:-224/n_sgo:8/walk:1"}
RECORDS = {"id": "haptic.rate", "section": "haptic", "name": "servo loop rate", "goal": 1000, "tolerance": 0.1,
           "unit": "Hz", "comparison": "within", "format": ".2f", "measures": "The servo loop's rate.",
           "file": "haptic_loop.jsonl", "select": {"setup": "servo", "loaded": False}, "key": "rate_hz"}


def load(tmp_path, *specs):
    path = tmp_path / "targets.yaml"
    path.write_text(yaml.safe_dump(list(specs)))
    return targets.load(str(path), report.sections.NAMES), str(path)


def refused(tmp_path, *specs, raw=None):
    with pytest.raises(TargetsError) as error:
        loaded, _ = load(tmp_path, *specs)
        if raw is not None:
            targets.check_raw(loaded, raw)
    return str(error.value)


def test_the_committed_targets_are_good():
    targets.check_raw(report.load_targets(), RAW)
    targets.check_raw(report.load_targets(), os.path.join(ROOT, "bench", "raw", "scale"), "scale")


def test_a_good_target_loads(tmp_path):
    loaded, _ = load(tmp_path, GOOD, RECORDS)
    targets.check_raw(loaded, RAW)
    assert loaded.get("contact.plate").goal_column() == "<= 2 us"
    assert loaded.get("haptic.rate").goal_column() == "1000 Hz +- 0.1 %"


def test_a_target_without_a_goal_is_refused_naming_it_and_the_file(tmp_path):
    message = refused(tmp_path, {k: v for k, v in GOOD.items() if k != "goal"})
    assert "target 'contact.plate'" in message and "no goal" in message
    assert str(tmp_path / "targets.yaml") in message


def test_an_unknown_benchmark_is_refused_naming_the_target_and_the_raw_file(tmp_path):
    message = refused(tmp_path, GOOD, dict(GOOD, id="contact.typo", benchmark="BM_ContactAreaOnly/mesh:-225"), raw=RAW)
    assert "target 'contact.typo'" in message
    assert "'BM_ContactAreaOnly/mesh:-225'" in message and "contact_area.json" in message
    assert str(tmp_path / "targets.yaml") in message


def test_an_unknown_divisor_counter_or_family_is_refused(tmp_path):
    assert "'BM_Nope'" in refused(tmp_path, dict(GOOD, over="BM_Nope"), raw=RAW)
    assert "counter 'crossing'" in refused(tmp_path, dict(GOOD, per="crossing"), raw=RAW)
    assert "'BM_Nope/*'" in refused(tmp_path, dict(GOOD, benchmark="BM_Nope/*", worst=True), raw=RAW)


def test_records_that_no_line_has_or_a_key_they_lack_are_refused(tmp_path):
    message = refused(tmp_path, dict(RECORDS, select={"setup": "servo/typo"}), raw=RAW)
    assert "target 'haptic.rate'" in message and "haptic_loop.jsonl" in message and "servo/typo" in message
    message = refused(tmp_path, dict(RECORDS, key="rate_khz"), raw=RAW)
    assert "key 'rate_khz'" in message and "haptic_loop.jsonl" in message
    assert "key 'period_us.p98'" in refused(tmp_path, dict(RECORDS, key="period_us.p98"), raw=RAW)


def test_a_target_whose_raw_file_is_absent_is_not_checked(tmp_path):
    loaded, _ = load(tmp_path, dict(GOOD, file="contact_area_gone.json"))
    targets.check_raw(loaded, RAW)


@pytest.mark.parametrize("change, words", [
    ({"goal": "fast"}, "goal 'fast' is not a number"),
    ({"comparison": "<"}, "comparison '<' is none of"),
    ({"section": "contacts"}, "section 'contacts' is none of the report's"),
    ({"format": "%.2f"}, "format '%.2f' is not a number format"),
    ({"goals": 2}, "unknown field(s) goals"),
    ({"comparison": "reported"}, "a reported figure has no goal"),
    ({"comparison": "within"}, "a tolerance (%) goes with comparison 'within'"),
    ({"comparison": ">="}, "a benchmark's target is checked as `<=`"),
    ({"file": "contact_area.csv"}, "neither a .json nor a .jsonl"),
    ({"key": "rate_hz"}, "field(s) key do not apply to contact_area.json"),
    ({"goal_text": "{comparison} {goal} {units}"}, "names a field it does not have"),
    ({"unit": None}, "unit is not a text"),
    ({"params": [0.05]}, "params is not a mapping"),
])
def test_a_malformed_target_is_refused_naming_it(tmp_path, change, words):
    message = refused(tmp_path, dict(GOOD, **change))
    assert "target 'contact.plate'" in message and words in message


def test_a_missing_field_a_twice_named_target_and_a_bad_file_are_refused(tmp_path):
    for field in targets.REQUIRED[1:]:
        assert f"no {field}" in refused(tmp_path, {k: v for k, v in GOOD.items() if k != field})
    assert "target #1: no id" in refused(tmp_path, {k: v for k, v in GOOD.items() if k != "id"})
    assert "target 'contact.plate' twice" in refused(tmp_path, GOOD, GOOD)
    assert "no benchmark" in refused(tmp_path, {k: v for k, v in GOOD.items() if k != "benchmark"})
    assert "no key" in refused(tmp_path, {k: v for k, v in RECORDS.items() if k != "key"})
    assert "key is a field name" in refused(tmp_path, dict(RECORDS, key=3))
    assert "select is not a mapping" in refused(tmp_path, dict(RECORDS, select="servo"))
    (tmp_path / "list.yaml").write_text("contact.plate: {goal: 2}\n")
    with pytest.raises(TargetsError, match="not a list of targets"):
        targets.load(str(tmp_path / "list.yaml"))
    with pytest.raises(TargetsError, match="cannot read it"):
        targets.load(str(tmp_path / "none.yaml"))


def test_a_goal_is_shown_as_written_and_checked_as_a_number(tmp_path):
    spec = dict(RECORDS, id="delay.energy", goal="-1e-4", unit="J", comparison=">=")
    del spec["tolerance"]
    loaded, _ = load(tmp_path, spec)
    target = loaded.get("delay.energy")
    assert target.goal_column() == ">= -1e-4 J"
    assert target.met(-1e-5) and not target.met(-2e-4)
    assert target.plain_verdict(-2e-4, "met up to 60 ms") == "missed (met up to 60 ms)"
