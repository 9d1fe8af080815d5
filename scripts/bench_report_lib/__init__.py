"""scripts/bench_report's code: bench/REPORT.md from the raw results of scripts/bench.

It lives beside its command, in scripts/, rather than in bench/: bench/'s *.py, *.cpp and *.h are
the measured code (a change there since the commit measured makes the report stale), and the
report's own code is not measured; scripts/ is the developer commands' folder, never installed.

- report.py: the report (and bench/SCALE.md) from a raw folder, and --check against the
  committed one;
- sections/: one module per report section, in sections.ORDER;
- targets.py: bench/targets.yaml read and checked, the Targets table; benchmark_targets.py: the
  targets that read a Google Benchmark file, measured alike;
- common.py: reading raw files, Measure (median, spread, paired ratios), percentiles, tables,
  figures; context.py: what a section is given, bench/benchmarks.yaml's names and its prose;
- prose/: each section's sentences as str.format templates; provenance.py: the commit measured;
  raw_copy.py: --keep, the compact copy of bench/out.

Goals and units are in bench/targets.yaml, benchmark names in bench/benchmarks.yaml (and the
targets' own in targets.yaml): the code holds none.
"""
