"""bench/REPORT.md (and bench/SCALE.md) from a raw results folder: the machine, the code measured,
the Targets table from bench/targets.yaml, bench/NOTES.md, then every section in its order."""
import difflib
import os
import re
import sys
import tempfile

from . import sections, targets
from .common import Figures, load_text, table
from .context import Context, Prose
from .provenance import code_since
from .sections import scale

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BENCH = os.path.join(ROOT, "bench")
TARGETS = os.path.join(BENCH, "targets.yaml")
BENCHMARKS = os.path.join(BENCH, "benchmarks.yaml")
TARGETS_HEADER = ["target", "goal", "measured (median)", "spread", "verdict"]


def load_targets(path=TARGETS):
    shown = os.path.relpath(path, ROOT) if path.startswith(ROOT) else path
    return targets.load(path, sections.NAMES, source=shown)


def _context(raw, out_dir, targets_path, section=None):
    checked = load_targets(targets_path)
    targets.check_raw(checked, raw, section)
    return Context(raw, checked, BENCHMARKS, Figures(os.path.join(out_dir, "figures")))


def render(raw, out_dir=BENCH, targets_path=TARGETS):
    """REPORT.md's text from `raw`; its figures written into out_dir/figures."""
    ctx = _context(raw, out_dir, targets_path)
    text = Prose("report")
    body = []
    for module in sections.ORDER:
        body += module.section(ctx)
    machine = load_text(os.path.join(raw, "machine.txt")).strip()
    notes_path = os.path.join(BENCH, "NOTES.md")
    notes = load_text(notes_path).strip() if os.path.exists(notes_path) else ""
    report = [text("title"), "", text("generated"), "", "```", machine, "```", "", *code_since(ROOT, text, machine),
              text("targets"), "", table(TARGETS_HEADER, ctx.targets.table_rows()), ""]
    if notes:
        report += [notes, ""]
    report += body
    return "\n".join(report) + "\n"


def write(raw, out_dir=BENCH, targets_path=TARGETS):
    report = render(raw, out_dir, targets_path)
    with open(os.path.join(out_dir, "REPORT.md"), "w") as handle:
        handle.write(report)
    print(f"bench_report: wrote bench/REPORT.md and {len(os.listdir(os.path.join(out_dir, 'figures')))} figures")
    return 0


def check(raw, committed=os.path.join(BENCH, "REPORT.md")):
    """0 when the report made from `raw` (its figures into a temporary folder) is `committed` byte
    for byte and every figure it links is in bench/figures; 1 with a diff otherwise."""
    with tempfile.TemporaryDirectory() as folder:
        report = render(raw, folder)
    with open(committed) as handle:
        current = handle.read()
    missing = [name for name in re.findall(r"\]\(figures/([^)]+)\)", report)
               if not os.path.exists(os.path.join(BENCH, "figures", name))]
    if report == current and not missing:
        print(f"bench_report: {os.path.relpath(committed, ROOT)} is what {raw} makes")
        return 0
    if missing:
        print(f"bench_report: bench/figures lacks {', '.join(missing)}")
    diff = difflib.unified_diff(current.splitlines(), report.splitlines(), "bench/REPORT.md (committed)",
                                f"made from {raw}", lineterm="", n=1)
    print("\n".join(list(diff)[:200]))
    print("bench_report: the committed report differs from what its raw results make: `scripts/bench --report` "
          "writes it (a change to scripts/bench_report_lib, bench/targets.yaml, bench/benchmarks.yaml or "
          "bench/NOTES.md changes it)")
    return 1


def write_scale(raw, out_dir=BENCH, targets_path=TARGETS):
    """bench/SCALE.md from RAW/mujoco_baseline.json alone (the scale section and its targets), its
    figure a file of its own (the full report's section 8 has scale_step_vs_objects.png)."""
    ctx = _context(raw, out_dir, targets_path, section="scale")
    body = scale.section(ctx, figure_name="scale_only_step_vs_objects.png")
    if not body:
        print(f"bench_report: no {raw}/mujoco_baseline.json", file=sys.stderr)
        return 1
    text = Prose("report")
    machine = load_text(os.path.join(raw, "machine.txt")).strip()
    report = [text("scale_title"), "", text("scale_generated"), "", "```", machine, "```", "",
              *code_since(ROOT, text, machine, "scripts/bench --scale"), text("targets"), "",
              table(TARGETS_HEADER, ctx.targets.table_rows()), ""]
    with open(os.path.join(out_dir, "SCALE.md"), "w") as handle:
        handle.write("\n".join(report + body) + "\n")
    print("bench_report: wrote bench/SCALE.md")
    return 0
