"""scripts/bench_report --keep: the compact copy of bench/out that the report reads and the
repository keeps (bench/raw/full)."""
import json
import os

from .common import load_json, load_jsonl
from .sections.sim import sim_errors

# Google Benchmark fields the report never reads.
DROPPED = ("family_index", "per_family_instance_index", "threads", "cpu_time", "aggregate_unit")


def keep_raw(out_dir, raw_dir):
    """Writes raw_dir, a compact copy of what the report reads from out_dir (scripts/bench's
    bench/out): Google Benchmark files without the machine's paths and host, and with only the
    repetitions and the median and standard deviation aggregates; sim_accuracy without its
    trajectories but with their errors against the reference; the rest as it is."""
    os.makedirs(raw_dir, exist_ok=True)
    for name in sorted(os.listdir(out_dir)):
        source = os.path.join(out_dir, name)
        target = os.path.join(raw_dir, name)
        if name.endswith(".json"):
            data = load_json(source)
            context = {k: data["context"][k] for k in ("date", "num_cpus", "library_build_type", "commit")
                       if k in data.get("context", {})}
            kept = [entry for entry in data["benchmarks"]
                    if entry.get("run_type") != "aggregate" or entry.get("aggregate_name") in ("median", "stddev")]
            benchmarks = [{k: v for k, v in entry.items() if k not in DROPPED} for entry in kept]
            with open(target, "w") as handle:
                json.dump({"context": context, "benchmarks": benchmarks}, handle, indent=0)
                handle.write("\n")
        elif name == "sim_accuracy.jsonl":
            runs = load_jsonl(source)
            for scenario in {r["scenario"] for r in runs}:
                group = [r for r in runs if r["scenario"] == scenario]
                reference = next((r for r in group if r.get("reference")), None)
                if reference is not None:
                    sim_errors(reference, [r for r in group if not r.get("reference")])
            with open(target, "w") as handle:
                for r in runs:
                    r.pop("trajectory", None)
                    handle.write(json.dumps(r) + "\n")
        elif name.endswith((".jsonl", ".txt")):
            with open(source) as handle:
                text = handle.read()
            if name == "machine.txt":
                text = text.rstrip("\n") + "\nraw:      compact copy of bench/out (scripts/bench_report --keep)\n"
            with open(target, "w") as handle:
                handle.write(text)
    print(f"bench_report: kept a compact copy of {out_dir} in {raw_dir}")
    return 0
